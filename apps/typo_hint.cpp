#include "apps/typo_hint.hpp"

#include <fmt/format.h>

#include <string_view>
#include <vector>

#include "core/spelling.hpp"

namespace covsim::app {

namespace {

std::vector<std::string> subcommand_names(CLI::App& app) {
  std::vector<std::string> out;
  for (const CLI::App* sub : app.get_subcommands({}))
    out.push_back(sub->get_name());
  return out;
}

// The long names of a command's options, with their dashes.
std::vector<std::string> option_names(CLI::App& command) {
  std::vector<std::string> out;
  for (const CLI::Option* o : command.get_options()) {
    for (const std::string& name : o->get_lnames())
      out.push_back("--" + name);
  }
  return out;
}

}  // namespace

std::optional<std::string> typo_hint(CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2) return std::nullopt;
  const std::string_view first = argv[1];
  if (first.empty() || first.front() == '-') return std::nullopt;
  CLI::App* command = nullptr;
  for (CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == first) command = sub;
  }
  if (command == nullptr) {
    const std::vector<std::string> names = subcommand_names(app);
    if (const auto near = closest_spelling(first, names))
      return fmt::format("'{}' is no covsim command: did you mean '{}'?", first, *near);
    return fmt::format("'{}' is no covsim command; the commands are {}", first,
                       fmt::join(names, ", "));
  }
  // An option of the subcommand, as given (before any '=value').
  const std::vector<std::string> names = option_names(*command);
  for (int i = 2; i < argc; ++i) {
    std::string_view word = argv[i];
    if (word.substr(0, 2) != "--") continue;
    word = word.substr(0, word.find('='));
    if (command->get_option_no_throw(std::string(word)) != nullptr) continue;
    // Every option as near ("--seeed": '--seed' or '--speed').
    if (const auto near = closest_spellings(word, names); !near.empty())
      return fmt::format("'{}' is no option of covsim {}: did you mean '{}'?", word, first,
                         fmt::join(near, "' or '"));
  }
  return std::nullopt;
}

}  // namespace covsim::app
