#pragma once
// "Did you mean" for the command line: when parsing fails on a word that is no subcommand or
// no option of the subcommand, the subcommand or option it most likely meant.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace covsim::app {

// A line such as "did you mean 'run'?" for the arguments that failed to parse, if one of
// them is a near miss of a subcommand or an option of the subcommand given.
std::optional<std::string> typo_hint(CLI::App& app, int argc, const char* const* argv);

}  // namespace covsim::app
