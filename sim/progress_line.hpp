#pragma once
// A status line on stderr for work that takes a while (a run, a video's encoding): nothing
// for a first quiet second, then redrawn at most twice a second on one line, and cleared
// when the work ends, so that what is printed next starts a clean line. Nothing at all when
// stderr is not a terminal (a log, a pipe, a sweep's worker).
#include <chrono>
#include <string>

namespace covsim {

class ProgressLine {
 public:
  // shown: whether to draw the line (default: stderr is a terminal).
  explicit ProgressLine(bool shown = stderr_is_terminal());
  ~ProgressLine();  // clears, also when the work ends by an exception
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // Whether a line would be drawn now: shown, past the quiet second, and half a second
  // after the last one. A caller builds its text only then.
  bool due() const;
  // Draws `text` in place of the last line (if shown), ending the wait for the next.
  void show(const std::string& text);
  void clear();
  // Whether a line is on the terminal now.
  bool drawn() const { return drawn_; }
  // Wall-clock seconds since the line was made.
  double seconds() const;
  static bool stderr_is_terminal();

 private:
  bool shown_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace covsim
