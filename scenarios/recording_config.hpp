#pragma once
// What a run's folder records: "recording": {"trajectory_period": s}.

namespace covsim {

struct RecordingConfig {
  // Seconds between a robot's rows in trajectory.csv; 0 writes every motion step.
  double trajectory_period = 0.0;
};

}  // namespace covsim
