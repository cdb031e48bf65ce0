#pragma once
// Where a result came from: covsim's version, the git commit of its sources (and whether the
// tree was dirty), the compiler, the build type and the flags that affect results. Written
// into final.json, a sweep's sweep.json and a trace's header; a replay or a resumed sweep
// says when the build differs from the one that wrote them.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/trace.hpp"

namespace covsim {

// This build's provenance as a JSON object (keys version, commit, dirty, compiler,
// build_type, flags).
nlohmann::ordered_json this_build();
// One line: "covsim 0.3.0 (commit a49cd7c5b149, dirty; GNU 12.2.0, Release; -O2 ...)".
std::string describe_build(const nlohmann::json& provenance);
// What differs between a recorded provenance and this build, one line per key ("commit: X
// then, Y now"); empty when nothing does (two dirty builds of one commit may still differ).
std::vector<std::string> build_differences(const nlohmann::json& recorded);
// The same between two recorded provenances, each line `pattern` formatted with the key and
// the two values.
std::vector<std::string> build_differences(const nlohmann::json& a, const nlohmann::json& b,
                                           std::string_view pattern = "{}: {} and {}");
// The provenance as trace header entries, and back.
void add_provenance(TraceHeader& header);
nlohmann::json provenance_of(const TraceHeader& header);

}  // namespace covsim
