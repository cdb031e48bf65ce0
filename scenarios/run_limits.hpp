#pragma once
// How large a run may grow before it starts: "limits": {"motion_steps": n,
// "trajectory_rows": n}. A scenario over a limit is refused at load time with an error naming
// the key that makes it large and this one, which raises the bound deliberately.

#include "core/config_key.hpp"

namespace covsim {

struct RunLimits {
  // Motion steps per robot until max_time (max_time / loops.loop2_period).
  double motion_steps = 1e8;
  // Rows trajectory.csv may reach (robots x rows per robot; about 150 bytes each).
  double trajectory_rows = 2e7;
};

// Its keys, declared once with their schemas (defaults from the struct above).
ConfigKeys<RunLimits> limit_keys();

}  // namespace covsim
