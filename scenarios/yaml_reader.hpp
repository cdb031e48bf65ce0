#pragma once
// Reading YAML input into the JSON that JsonValue reads, as strictly as parse_json reads
// JSON, keeping where each value starts. yaml-cpp stays inside yaml_reader.cpp: nothing that
// includes this header compiles against it.
#include <string>

#include "scenarios/input_file.hpp"

namespace covsim {

// Parses one YAML 1.2 document by the core schema: plain 1, -2, 0x1f and 0o17 are integers
// and 1.5, 1e3 and .5 floats, each the number parse_json makes of the same digits (the same
// double, bit for bit); true and false are booleans; null, ~ and nothing are null; every other
// scalar, and every quoted or block one, is a string. ScenarioErrors name `source` and the
// line and column (with the JSON path where there is a value): malformed YAML, a scalar that
// is not UTF-8, a duplicate key, a key that is not a string, nesting deeper than kMaxJsonDepth,
// .inf and .nan, a number beyond a double's range, anchors and aliases, merge keys (<<), tags other
// than the core schema's, and a second document.
InputFile parse_yaml(const std::string& text, const std::string& source);

}  // namespace covsim
