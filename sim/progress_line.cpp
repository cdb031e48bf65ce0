#include "sim/progress_line.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace covsim {

namespace {
constexpr std::chrono::milliseconds kQuiet{1000};  // work shorter than this shows nothing
constexpr std::chrono::milliseconds kEvery{500};   // between two lines
constexpr int kWidth = 78;
}  // namespace

bool ProgressLine::stderr_is_terminal() {
  return isatty(STDERR_FILENO) != 0;
}

ProgressLine::ProgressLine(bool shown)
    : shown_(shown), start_(std::chrono::steady_clock::now()), last_(start_) {}

ProgressLine::~ProgressLine() {
  clear();
}

bool ProgressLine::due() const {
  if (!shown_) return false;
  const auto now = std::chrono::steady_clock::now();
  return now - start_ >= kQuiet && now - last_ >= kEvery;
}

void ProgressLine::show(const std::string& text) {
  if (!shown_) return;
  last_ = std::chrono::steady_clock::now();
  fmt::print(stderr, "\r{:<{}}", text, kWidth);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::clear() {
  if (!drawn_) return;
  fmt::print(stderr, "\r{:<{}}\r", "", kWidth);
  std::fflush(stderr);
  drawn_ = false;
}

double ProgressLine::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace covsim
