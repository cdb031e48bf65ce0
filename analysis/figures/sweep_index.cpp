#include "analysis/figures/sweep_index.hpp"

#include <fmt/format.h>

#include <fstream>
#include <string>

#include "analysis/figures/html_escape.hpp"
#include "analysis/sweep/sweep_tables.hpp"
#include "io/atomic_file.hpp"

namespace covsim {

namespace fs = std::filesystem;

namespace {

// The fields of one CSV line (RFC 4180 quotes).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else if (c != '\r') {
      out.back() += c;
    }
  }
  return out;
}

std::string summary_table(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return "<p>No summary.csv in this folder.</p>\n";
  std::string html = "<div class=\"scroll\"><table id=\"summary\">\n";
  std::string line;
  for (bool head = true; std::getline(in, line); head = false) {
    html += "<tr>";
    const char* cell = head ? "th" : "td";
    for (const std::string& f : csv_fields(line))
      html += fmt::format("<{0}>{1}</{0}>", cell, html_escape(f));
    html += "</tr>\n";
  }
  return html + "</table></div>\n";
}

}  // namespace

void write_sweep_index(const fs::path& dir, const SweepSpec& spec,
                       const std::vector<SweepResult>& results,
                       const std::vector<fs::path>& charts) {
  std::size_t failed = 0, converged = 0;
  for (const SweepResult& r : results) {
    failed += r.error ? 1 : 0;
    converged += (!r.error && r.converged()) ? 1 : 0;
  }
  std::string settings = "<table id=\"settings\">\n<tr><th>setting</th>";
  for (const std::string& p : spec.parameters)
    settings += fmt::format("<th>{}</th>", html_escape(p));
  settings += "</tr>\n";
  for (std::size_t s = 0; s < spec.settings.size(); ++s) {
    settings += fmt::format("<tr><td>{}</td>", s);
    for (const auto& v : spec.settings[s])
      settings += fmt::format("<td>{}</td>", html_escape(csv_value(v)));
    settings += "</tr>\n";
  }
  settings += "</table>\n";
  std::string figures;
  for (const fs::path& c : charts) {
    const std::string name = html_escape(c.filename().string());
    const std::string shown =
        c.extension() == ".pdf"
            ? fmt::format(
                  "<object data=\"{0}\" type=\"application/pdf\"><a href=\"{0}\">{0}</a>"
                  "</object>",
                  name)
            : fmt::format("<img src=\"{0}\" alt=\"{0}\">", name);
    figures += fmt::format("<figure class=\"chart\">{}<figcaption>{}</figcaption></figure>\n",
                           shown, html_escape(c.stem().string()));
  }
  const std::string title = html_escape(dir.filename().string());
  AtomicFile f(dir / "index.html");
  f.stream() << fmt::format(
      R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{0}: covsim sweep</title>
<style>
body {{ font-family: sans-serif; margin: 1.5em; }}
table {{ border-collapse: collapse; font-size: 0.85em; }}
td, th {{ border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: right; }}
.scroll {{ overflow-x: auto; }}
figure.chart {{ display: inline-block; margin: 0.5em; }}
figure.chart img {{ max-width: 640px; }}
</style></head><body>
<h1>{0}</h1>
<p>Sweep: {1}. {2} settings &times; {3} seeds = {4} runs: {5} converged, {6} failed.
The runs, one row each: <a href="runs.csv">runs.csv</a>; the summary: <a href="summary.csv">summary.csv</a>.</p>
<h2>Settings</h2>
{7}<h2>Summary</h2>
{8}<h2>Charts ({9})</h2>
<p>Each measure that differs between the runs, against each numeric swept parameter: the mean
with its 95% confidence band, the runs as dots.</p>
<div id="charts">
{10}</div>
</body></html>
)",
      title, html_escape(spec.source), spec.settings.size(), spec.seeds.size(), results.size(),
      converged, failed, settings, summary_table(dir / "summary.csv"), charts.size(), figures);
  f.commit();
}

}  // namespace covsim
