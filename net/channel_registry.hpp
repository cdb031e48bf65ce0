#pragma once
// The channel models by name (the scenario's network.channel.type): the one list of them.
#include "net/channel_model.hpp"

namespace covsim {

Registry<ChannelEntry>& channel_registry();

}  // namespace covsim
