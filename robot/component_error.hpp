#pragma once
// An error raised by (or caught from) one robot's component during a run: what it was, whose,
// and when, with the original exception nested (std::nested_exception) so that a front end
// can re-raise it as it was (Python does, with this context as a note).
#include <stdexcept>
#include <string>

namespace covsim {

class ComponentError : public std::runtime_error, public std::nested_exception {
 public:
  // context: e.g. "robot 3's planner \"mine\" at t = 2.4 s"; what: the cause's message.
  ComponentError(std::string context, const std::string& what)
      : std::runtime_error(context + ": " + what), context_(std::move(context)) {}
  const std::string& context() const { return context_; }

 private:
  std::string context_;
};

}  // namespace covsim
