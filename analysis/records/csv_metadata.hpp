#pragma once
// A CSV file's columns described beside it, in the W3C's "CSV on the Web" metadata format
// (Metadata Vocabulary for Tabular Data): FILE-metadata.json next to FILE, the name CSVW
// processors look for first. Each column has its header, its datatype as the file writes it
// (booleans as 1 and 0), its description and its unit (schema.org's unitText), so that a
// table read by another tool keeps its units.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/records/field_table.hpp"

namespace covsim {

struct CsvColumn {
  std::string name;
  FieldKind kind = FieldKind::number;
  std::string unit;  // empty for counts and pure numbers
  std::string description;
};

// The columns' header line (without its newline), names quoted where CSV needs it.
std::string csv_header(const std::vector<CsvColumn>& columns);
// The metadata document of `csv` (a file name, relative to the metadata file).
nlohmann::ordered_json csv_metadata(const std::string& csv, const std::string& title,
                                    const std::vector<CsvColumn>& columns);
// Writes csv_metadata beside `csv_file` (whole or not at all).
void write_csv_metadata(const std::filesystem::path& csv_file, const std::string& title,
                        const std::vector<CsvColumn>& columns);

}  // namespace covsim
