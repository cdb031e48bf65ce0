// The layers a scene or a video frame draws (analysis/figures/layers): --layers' lists, their
// errors, and the table docs/outputs.md gives, read from the declarations.
#include <catch2/catch.hpp>

#include "analysis/figures/layers.hpp"
#include "tests/doc_text.hpp"

using namespace covsim;

TEST_CASE("a list of layers draws those alone", "[layers]") {
  const Layers l = parse_layers("robots,paths");
  CHECK(l.has(Layer::robots));
  CHECK(l.has(Layer::paths));
  CHECK_FALSE(l.has(Layer::virtual_paths));
  CHECK_FALSE(l.has(Layer::legend));
  CHECK(parse_layers("all") == Layers::all());
  CHECK(parse_layers("legend,all") == Layers::all());
}

TEST_CASE("a minus takes a layer away; a list that starts with one starts from all", "[layers]") {
  const Layers l = parse_layers("all,-virtual-paths,-cells");
  CHECK_FALSE(l.has(Layer::virtual_paths));
  CHECK_FALSE(l.has(Layer::cells));
  CHECK(l.has(Layer::real_cells));
  CHECK(l.has(Layer::robots));
  CHECK(parse_layers("-virtual-paths") == parse_layers("all,-virtual-paths"));
  CHECK(parse_layers("robots,paths,-paths") == parse_layers("robots"));
}

TEST_CASE("every layer has a name that reads back as itself", "[layers]") {
  REQUIRE(layer_table().size() == static_cast<std::size_t>(Layer::count_));
  for (const LayerInfo& info : layer_table()) {
    INFO(info.name);
    const Layers only = parse_layers(info.name);
    CHECK(only.has(info.layer));
    CHECK(only == Layers::none().add(info.layer));
    CHECK_FALSE(parse_layers("-" + std::string(info.name)).has(info.layer));
    CHECK_FALSE(info.what.empty());
  }
}

TEST_CASE("an unknown or empty name, or nothing left, is an error listing the layers", "[layers]") {
  const std::string names = layer_names();
  CHECK_THAT(names, Catch::StartsWith("obstacles, density, cells, real-cells, paths"));
  CHECK_THROWS_WITH(parse_layers("robots,pathz"),
                    Catch::Contains("unknown layer \"pathz\"") && Catch::Contains(names));
  CHECK_THROWS_WITH(parse_layers("robots,,paths"), Catch::Contains("empty layer name"));
  CHECK_THROWS_WITH(parse_layers(""), Catch::Contains("empty layer name"));
  CHECK_THROWS_WITH(parse_layers("-all"), Catch::Contains("nothing to draw"));
  CHECK_THROWS_WITH(parse_layers("robots,-robots"), Catch::Contains("no layer left"));
  CHECK_THROWS_AS(parse_layers("Robots"), std::invalid_argument);
}

TEST_CASE("docs/outputs.md's table of layers is the declared one", "[layers]") {
  std::string table =
      "| layer | what it draws |\n"
      "|---|---|\n";
  for (const LayerInfo& l : layer_table())
    table += "| `" + std::string(l.name) + "` | " + std::string(l.what) + " |\n";
  const std::string text = test::doc_text("outputs.md");
  INFO("docs/outputs.md should hold:\n" << table);
  const auto at = text.find("| layer | what it draws |");
  REQUIRE(at != std::string::npos);
  CHECK(text.substr(at, text.find("\n\n", at) - at + 1) == table);
}
