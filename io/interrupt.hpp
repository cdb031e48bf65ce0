#pragma once
// SIGINT and SIGTERM as a request to stop. The command-line program installs the handlers;
// the kernel looks at the flag after each event and throws Interrupted, so that what a run
// was writing unwinds (partial files removed, a created folder taken back) and the program
// exits with 128 + the signal's number. Without the handlers (a library user, Python) the
// flag never rises.
#include <stdexcept>

namespace covsim {

struct Interrupted : std::runtime_error {
  explicit Interrupted(int signal);
  int signal;
};

void install_interrupt_handlers();
// The signal received since the handlers were installed, or 0.
int pending_interrupt();

}  // namespace covsim
