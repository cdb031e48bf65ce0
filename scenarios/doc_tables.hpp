#pragma once
// docs/scenario-format.md's tables of the fixed sections' keys, generated from their schemas
// (scenario_sections.hpp): each sits between "<!-- begin NAME -->" and "<!-- end NAME -->"
// lines, the prose around it written by hand. `covsim list sections --markdown` prints them,
// `covsim list --update-docs FILE` writes them into the file, and a test fails when the file
// differs from the schemas.
#include <optional>
#include <string>
#include <vector>

namespace covsim {

struct DocTable {
  std::string name;  // the section's path
  std::string markdown;
};

std::vector<DocTable> scenario_doc_tables();
// The table between the markers of `name` in a document, or nullopt without them.
std::optional<std::string> doc_table_in(const std::string& text, const std::string& name);
// The document with that table replaced; throws std::invalid_argument without the markers.
std::string with_doc_table(const std::string& text, const DocTable& table);
// A table with its markers, as it stands in the document.
std::string marked(const DocTable& table);

}  // namespace covsim
