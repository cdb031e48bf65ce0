// `covsim list [WHAT] [--names]`: every registered component with its description and
// parameters (kind, default, unit, bounds), and every fixed section of a scenario with its
// keys, in the spirit of ns-3's attribute listing. WHAT is a component listing (a row of
// component_sections()), "sections", or one section ("sensor"). `--names` prints the
// names alone, one per line, for scripts (a section's keys as dotted paths);
// `--reads-range` keeps the planners whose steps depend on the sensor's range; `--markdown`
// prints the sections' tables as docs/scenario-format.md holds them, and `--update-docs FILE`
// writes them into that file.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <functional>
#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/plugin_loader.hpp"
#include "io/atomic_file.hpp"
#include "io/bounded_read.hpp"
#include "scenarios/component_sections.hpp"
#include "scenarios/doc_tables.hpp"
#include "scenarios/scenario_sections.hpp"

namespace covsim::app {

namespace {
// A line on what the entry reads besides its parameters ("" for none).
template <class Entry>
std::string reads(const Entry&) {
  return "";
}
std::string reads(const PlannerEntry& e) {
  return e.reads_range ? "    reads the range sensor: its steps depend on sensor.range\n" : "";
}
std::string reads(const LawEntry& e) {
  return e.autonomous ? "" : "    targets set by a driving program: never converges by itself\n";
}

template <class Entry>
Entry entry_of(const ComponentSection<Entry>&);  // the row's entry type, in decltype only

// "network": {"loss": {"model"}}: where a section's type key sits in a scenario.
std::string where(const std::string& path, const std::string& type_key) {
  std::string out = fmt::format("{{\"{}\"}}", type_key);
  std::string rest = path;
  for (auto dot = rest.rfind('.');; dot = rest.rfind('.')) {
    const std::string key = dot == std::string::npos ? rest : rest.substr(dot + 1);
    out = fmt::format("\"{}\": {}", key, out);
    if (dot == std::string::npos) break;
    out = "{" + out + "}";
    rest = rest.substr(0, dot);
  }
  return out;
}

template <class Entry>
void print(const ComponentSection<Entry>& row, bool names_only,
           const std::function<bool(const Entry&)>& keep = {}) {
  if (names_only) {
    for (const Entry& e : row.registry().entries())
      if (!keep || keep(e)) std::cout << e.name << '\n';
    return;
  }
  std::cout << fmt::format("{} ({}):\n", row.listing, where(row.path, row.type_key));
  for (const Entry& e : row.registry().entries()) {
    if (keep && !keep(e)) continue;
    std::cout << fmt::format("  {}: {}\n", e.name, e.description) << reads(e);
    if (e.params.empty())
      std::cout << "    (no parameters)\n";
    else
      std::cout << describe(e.params, "    ");
  }
}

void print(const ScenarioSection& section, bool names_only) {
  if (names_only) {
    for (const ParamSpec& spec : section.schema())
      std::cout << section.path << '.' << spec.name << '\n';
    return;
  }
  std::cout << fmt::format("section {}: {}\n", section.path, section.description)
            << describe(section.schema(), "  ");
}

void update_docs(const std::string& file) {
  std::string text;
  try {
    text = read_whole_file(file);
  } catch (const InputReadError& e) {
    throw InputError(fmt::format("list --update-docs: {}", e.what()));
  }
  for (const DocTable& table : scenario_doc_tables()) {
    try {
      text = with_doc_table(text, table);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("list --update-docs: {}: {}", file, e.what()));
    }
  }
  AtomicFile out(file);
  out.stream() << text;
  out.commit();
}

// What `list` can show: the component listings, "sections" and each section.
std::vector<std::string> component_listings() {
  std::vector<std::string> out;
  for_each_component_section([&](const auto& row) { out.push_back(row.listing); });
  return out;
}

std::vector<std::string> listings() {
  std::vector<std::string> out = component_listings();
  out.emplace_back("sections");
  for (const ScenarioSection& s : scenario_sections())
    out.push_back(s.path);
  return out;
}
}  // namespace

void add_list_command(CLI::App& app) {
  struct Options {
    std::string what;
    bool names = false;
    bool reads_range = false;
    bool autonomous = false;
    bool markdown = false;
    std::string update_docs;
    std::vector<std::string> plugins;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "list",
      "List the registered components of every extension point, and the keys of a "
      "scenario's fixed sections");
  cmd->add_option("WHAT", o->what,
                  fmt::format("{}, sections, or a section such as sensor (default: all)",
                              fmt::join(component_listings(), ", ")))
      ->check(CLI::IsMember(listings()));
  cmd->add_flag("--names", o->names, "Names only, one per line");
  cmd->add_flag("--reads-range", o->reads_range,
                "Planners only: those whose steps depend on the range sensor's range");
  cmd->add_flag("--autonomous", o->autonomous,
                "Laws only: those that compute their own targets (not set by a driving program)");
  cmd->add_flag("--markdown", o->markdown,
                "Sections only: their tables as docs/scenario-format.md holds them");
  cmd->add_option("--update-docs", o->update_docs,
                  "Write the sections' tables into FILE (docs/scenario-format.md) between its "
                  "<!-- begin NAME --> and <!-- end NAME --> lines");
  add_plugin_option(cmd, o->plugins);
  cmd->callback([o] {
    load_plugins(o->plugins);
    if (!o->update_docs.empty()) return update_docs(o->update_docs);
    const bool all = o->what.empty();
    bool is_section = o->what == "sections";
    for (const ScenarioSection& s : scenario_sections())
      is_section = is_section || s.path == o->what;
    if (all && o->names) throw InputError("list: --names needs WHAT (planners, laws, ...)");
    if (o->reads_range && o->what != "planners")
      throw InputError(
          "list: --reads-range applies to planners only (list planners --reads-range)");
    if (o->autonomous && o->what != "laws")
      throw InputError("list: --autonomous applies to laws only (list laws --autonomous)");
    if (o->markdown && !(is_section || all))
      throw InputError("list: --markdown applies to sections only (list sections --markdown)");
    if (o->markdown) {
      for (const DocTable& table : scenario_doc_tables())
        if (all || o->what == "sections" || o->what == table.name) std::cout << marked(table);
      return;
    }
    // A blank line between listings (not between names).
    bool first = true;
    const auto gap = [&] {
      if (!first && !o->names) std::cout << '\n';
      first = false;
    };
    for_each_component_section([&](const auto& row) {
      if (!all && o->what != row.listing) return;
      using Entry = decltype(entry_of(row));
      std::function<bool(const Entry&)> keep;
      if constexpr (std::is_same_v<Entry, PlannerEntry>) {
        if (o->reads_range) keep = [](const PlannerEntry& e) { return e.reads_range; };
      }
      if constexpr (std::is_same_v<Entry, LawEntry>) {
        if (o->autonomous) keep = [](const LawEntry& e) { return e.autonomous; };
      }
      gap();
      print(row, o->names, keep);
    });
    for (const ScenarioSection& s : scenario_sections()) {
      if (!all && o->what != "sections" && o->what != s.path) continue;
      gap();
      print(s, o->names);
    }
  });
}

}  // namespace covsim::app
