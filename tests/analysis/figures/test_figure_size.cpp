// Figure sizes (analysis/figures/figure_size): the presets, a width in millimetres, and the
// table docs/outputs.md gives, read from the presets.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include "analysis/figures/figure_size.hpp"
#include "tests/doc_text.hpp"

using namespace covsim;

TEST_CASE("a paper's column, its page and a slide, in points", "[figure_size]") {
  const auto column = parse_figure_size("column");
  REQUIRE(column);
  CHECK(column->width == Approx(88 * 72 / 25.4));  // 249.4 pt
  CHECK(column->height == 0);
  CHECK(column->font == 8);
  const auto page = parse_figure_size("page");
  REQUIRE(page);
  CHECK(page->width == Approx(180 * 72 / 25.4));
  CHECK(page->font == 9);
  const auto talk = parse_figure_size("talk");
  REQUIRE(talk);
  CHECK(talk->width == Approx(960));  // 16:9, 1920 × 1080 pixels at two a point
  CHECK(talk->height == Approx(540));
  CHECK(talk->font == 16);
  CHECK(default_figure_size().width == page->width);
  CHECK(default_size_preset().name == "page");
}

TEST_CASE("a width in millimetres keeps the default text", "[figure_size]") {
  const auto w = parse_figure_size("120mm");
  REQUIRE(w);
  CHECK(w->width == Approx(120 * 72 / 25.4));
  CHECK(w->font == default_figure_size().font);
  CHECK(parse_figure_size("30mm"));
  CHECK(parse_figure_size("1000mm"));
  for (const char* bad :
       {"", "mm", "120", "120 mm", "29mm", "1001mm", "-5mm", "nanmm", "Page", "120mmx", "1e9mm"}) {
    INFO(bad);
    CHECK_FALSE(parse_figure_size(bad));
  }
  CHECK(figure_size_choices() == "column, page, talk, or a width such as 120mm (30 to 1000 mm)");
}

TEST_CASE("docs/outputs.md's table of sizes is the presets'", "[figure_size]") {
  std::string table =
      "| size | width | height | text | for |\n"
      "|---|---|---|---|---|\n";
  for (const SizePreset& p : size_presets())
    table += fmt::format(
        "| `{}` | {:.4g} mm | {} | {:g} pt | {} |\n", p.name, p.width_mm,
        p.height_mm > 0 ? fmt::format("{:.4g} mm", p.height_mm) : std::string("the figure's own"),
        p.font_pt, p.use);
  const std::string text = test::doc_text("outputs.md");
  INFO("docs/outputs.md should hold:\n" << table);
  const auto at = text.find("| size | width |");
  REQUIRE(at != std::string::npos);
  CHECK(text.substr(at, text.find("\n\n", at) - at + 1) == table);
}
