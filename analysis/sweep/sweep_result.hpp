#pragma once
// One run of a sweep as its folder keeps it: DIR/runs/<index>.json, the run's measures (the
// run fields, by name) or why it failed.
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace covsim {

struct SweepResult {
  std::size_t index = 0;
  std::optional<std::string> error;  // the run failed: why
  nlohmann::ordered_json values = nlohmann::ordered_json::object();
  double number(const std::string& field) const;  // NaN if absent
  bool converged() const;
  std::string fingerprint() const;
};

// DIR/runs/<index>.json.
std::filesystem::path result_file(const std::filesystem::path& dir, std::size_t index);
// Written whole or not at all (AtomicFile).
void write_result(const std::filesystem::path& dir, const SweepResult& result);
// The result of run `index` kept in DIR, or nothing when it is absent, damaged, of another
// run, or lacks a measure of this build (it is then run again).
std::optional<SweepResult> read_result(const std::filesystem::path& dir, std::size_t index);

}  // namespace covsim
