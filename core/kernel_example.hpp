#pragma once
// A small synthetic model that exercises every kernel feature: periodic timers at
// different rates and phases, random message delays, timeouts that are rescheduled and
// cancelled, stop conditions and state checkpoints. It demonstrates the kernel and pins
// its behaviour down in the golden-fingerprint test.
#include <cstdint>

#include "core/kernel.hpp"
#include "core/sim_time.hpp"

namespace covsim {

struct KernelExampleConfig {
  std::uint32_t entities = 8;
  SimTime until = SimTime::from_ns(20'000'000'000);  // 20 s
};

struct KernelExampleResult {
  std::uint64_t events = 0;
  std::uint64_t messages = 0;
  std::uint64_t timeouts = 0;
  SimTime end_time;
  std::uint64_t fingerprint = 0;
};

// Builds the model in the kernel and runs it until config.until.
KernelExampleResult run_kernel_example(Kernel& kernel, const KernelExampleConfig& config);

}  // namespace covsim
