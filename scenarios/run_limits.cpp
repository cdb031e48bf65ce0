#include "scenarios/run_limits.hpp"

namespace covsim {

ConfigKeys<RunLimits> limit_keys() {
  const RunLimits d;
  return {
      member_key<RunLimits>(ParamSpec::number("motion_steps", "steps",
                                              "motion steps per robot until max_time (max_time / "
                                              "loops.loop2_period)")
                                .positive()
                                .defaults_to(d.motion_steps),
                            &RunLimits::motion_steps),
      member_key<RunLimits>(
          ParamSpec::number("trajectory_rows", "rows",
                            "rows trajectory.csv may reach: robots × (max_time / the larger "
                            "of loop2_period and recording.trajectory_period), about 150 "
                            "bytes each")
              .positive()
              .defaults_to(d.trajectory_rows),
          &RunLimits::trajectory_rows)};
}

}  // namespace covsim
