#pragma once
// A sweep folder remembers its sweep (DIR/sweep.json: the resolved spec and the provenance of
// the build that started it), so that a resume or a merge cannot mix two sweeps' results and
// says when builds differ.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "analysis/sweep/sweep_spec.hpp"

namespace covsim {

struct SweepFolderRecord {
  nlohmann::json sweep;       // the resolved spec (to_json(SweepSpec))
  nlohmann::json provenance;  // the build that started it; {} if unrecorded
};

// DIR/sweep.json. Throws std::runtime_error naming the file when it is missing or malformed.
SweepFolderRecord read_sweep_folder(const std::filesystem::path& dir);
// The sweep a folder's sweep.json holds; one that covsim did not write (a list of the wrong
// length, a missing key, a wrong type) is a ScenarioError naming the file.
SweepSpec sweep_of_folder(const std::filesystem::path& dir);

// Makes DIR the folder of `spec`: writes DIR/sweep.json with this build's provenance, or, when
// DIR already holds one, checks that it is the same sweep (std::runtime_error if not) and
// warns on stderr when another build started it.
void claim_sweep_folder(const SweepSpec& spec, const std::filesystem::path& dir);

// Writes DIR/sweep.json as `record` holds it.
void write_sweep_folder(const std::filesystem::path& dir, const SweepFolderRecord& record);

}  // namespace covsim
