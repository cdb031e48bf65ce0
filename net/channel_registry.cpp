#include "net/channel_registry.hpp"

#include "net/channel.hpp"
#include "net/ns3_wifi_channel.hpp"

namespace covsim {

Registry<ChannelEntry>& channel_registry() {
  static Registry<ChannelEntry> registry("channel model",
                                         {abstract_channel_entry(), ns3_wifi_channel_entry()});
  return registry;
}

}  // namespace covsim
