#include <catch2/catch.hpp>

#include "core/spelling.hpp"

using namespace covsim;

TEST_CASE("spelling distance counts insertions, deletions, substitutions and swaps", "[spelling]") {
  CHECK(spelling_distance("run", "run") == 0);
  CHECK(spelling_distance("rnu", "run") == 1);  // a swap of neighbours
  CHECK(spelling_distance("rn", "run") == 1);
  CHECK(spelling_distance("runn", "run") == 1);
  CHECK(spelling_distance("ran", "run") == 1);
  CHECK(spelling_distance("", "run") == 3);
  CHECK(spelling_distance("plot", "list") == 3);
}

TEST_CASE("the closest name is offered only when it is a likely typo", "[spelling]") {
  const std::vector<std::string> commands{"run", "plot", "sweep", "merge", "replay", "list"};
  CHECK(closest_spelling("rnu", commands) == "run");
  CHECK(closest_spelling("swep", commands) == "sweep");
  CHECK(closest_spelling("replya", commands) == "replay");
  CHECK_FALSE(closest_spelling("frobnicate", commands));  // nothing near
  CHECK_FALSE(closest_spelling("run", commands));         // nothing to correct
  // Two names equally near: no guess.
  CHECK_FALSE(closest_spelling("ab", {"aa", "bb"}));
}

TEST_CASE("every name as near is offered when several are", "[spelling]") {
  const std::vector<std::string> options{"--seed", "--set", "--speed", "--out"};
  CHECK(closest_spellings("--seeed", options) == std::vector<std::string>{"--seed", "--speed"});
  CHECK(closest_spellings("--outt", options) == std::vector<std::string>{"--out"});
  CHECK(closest_spellings("--seed", options).empty());  // nothing to correct
  CHECK(closest_spellings("--frobnicate", options).empty());
}
