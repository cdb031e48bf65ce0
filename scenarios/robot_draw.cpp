#include "scenarios/robot_draw.hpp"

namespace covsim {

namespace {
// The positions written back are the ones drawn: drawing again would move them.
std::optional<ParamValue> drawn_already(const RobotDraw&, const RunShape&) {
  return std::nullopt;
}
}  // namespace

ConfigKeys<RobotDraw> robot_draw_keys() {
  const RobotDraw d;
  ConfigKeys<RobotDraw> keys{
      member_key<RobotDraw>(
          ParamSpec::number("separation", "m",
                            "with \"count\": the least distance between two robots drawn")
              .non_negative()
              .derived("1/20 of √(area / count), the area being Ω's, the region's or the disk's"),
          &RobotDraw::separation),
      member_key<RobotDraw>(
          ParamSpec::number("jitter", "m",
                            "with \"positions\": each robot moves by a Gaussian step of this "
                            "standard deviation per coordinate, redrawn until it lands in Ω on "
                            "no other robot")
              .non_negative()
              .defaults_to(d.jitter),
          &RobotDraw::jitter)};
  for (ConfigKey<RobotDraw>& k : keys)
    k.get = drawn_already;
  return keys;
}

}  // namespace covsim
