#pragma once
// What a run's folder records: "recording": {"trajectory_period": s, "compress": b}.

#include "core/config_key.hpp"

namespace covsim {

struct RecordingConfig {
  // Seconds between a robot's rows in trajectory.csv; 0 writes every motion step.
  double trajectory_period = 0.0;
  // Writes trajectory.csv.gz (gzip) instead of trajectory.csv.
  bool compress = false;
};

// Its keys, declared once with their schemas (defaults from the struct above).
ConfigKeys<RecordingConfig> recording_keys();

}  // namespace covsim
