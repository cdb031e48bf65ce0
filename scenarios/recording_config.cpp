#include "scenarios/recording_config.hpp"

namespace covsim {

ConfigKeys<RecordingConfig> recording_keys() {
  const RecordingConfig d;
  return {member_key<RecordingConfig>(
              ParamSpec::number("trajectory_period", "s",
                                "simulated seconds between a robot's rows in trajectory.csv (0: "
                                "every motion step); the run is the same, only the file is "
                                "thinner")
                  .non_negative()
                  .defaults_to(d.trajectory_period),
              &RecordingConfig::trajectory_period),
          member_key<RecordingConfig>(
              ParamSpec::boolean("compress",
                                 "true writes trajectory.csv.gz (gzip) instead of trajectory.csv, "
                                 "as covsim run --compress does; the run is the same")
                  .defaults_to(d.compress),
              &RecordingConfig::compress)};
}

}  // namespace covsim
