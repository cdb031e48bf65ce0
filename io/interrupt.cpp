#include "io/interrupt.hpp"

#include <csignal>
#include <string>

namespace covsim {

namespace {
volatile std::sig_atomic_t received = 0;
extern "C" void on_signal(int s) {
  received = s;
}
}  // namespace

Interrupted::Interrupted(int s)
    : std::runtime_error(std::string("interrupted by ") + (s == SIGINT ? "SIGINT" : "SIGTERM")),
      signal(s) {}

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int pending_interrupt() {
  return received;
}

}  // namespace covsim
