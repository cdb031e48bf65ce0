#pragma once
// JSON laid out for a person: an object a key per line, an array of plain values (numbers,
// text, booleans, null) on one line ([0.35, 1.0]), any other array an element per line. A
// polygon reads a vertex per line, not a coordinate per line as nlohmann's dump(2) lays it
// out; the text parses back to the same value.
#include <string>

#include <nlohmann/json.hpp>

namespace covsim {

std::string readable_json(const nlohmann::json& j);
std::string readable_json(const nlohmann::ordered_json& j);

}  // namespace covsim
