#include "scenarios/input_file.hpp"

#include "io/bounded_read.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/yaml_reader.hpp"

namespace covsim {

TextPlace InputFile::place_of(std::string_view path) const {
  // A path the file has no value at (a key it lacks, an index past an array's end) falls
  // back to the object or array that should hold it.
  while (!path.empty()) {
    if (const auto it = places.find(std::string(path)); it != places.end()) return it->second;
    const std::size_t cut = path.find_last_of(".[");
    if (cut == std::string_view::npos) break;
    path = path.substr(0, cut);
  }
  return {};
}

ScenarioError InputFile::located(const ScenarioError& e) const {
  if (e.file() != source || e.path().empty() || e.place().known()) return e;
  const TextPlace place = place_of(e.path());
  if (!place.known()) return e;
  return ScenarioError(e.file(), place, e.path(), e.detail());
}

bool is_yaml_file(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  return ext == ".yaml" || ext == ".yml";
}

std::string read_text_file(const std::filesystem::path& file, std::string_view format) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw ScenarioError(file.string() + ": is a directory, not a " + std::string(format) + " file");
  try {
    return read_whole_file(file);
  } catch (const InputReadError& e) {
    throw ScenarioError(e.what());
  }
}

InputFile read_input(const std::filesystem::path& file) {
  if (is_yaml_file(file)) return parse_yaml(read_text_file(file, "YAML"), file.string());
  return InputFile{read_json_file(file), file.string(), {}};
}

nlohmann::json read_input_file(const std::filesystem::path& file) {
  return read_input(file).json;
}

}  // namespace covsim
