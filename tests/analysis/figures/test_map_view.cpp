// The map under a scene or video frame (analysis/figures/map_view): the density's colour bar.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "analysis/figures/map_view.hpp"
#include "scenarios/scenario.hpp"

using namespace covsim;

namespace {
Scenario square_with(const nlohmann::json& density) {
  const nlohmann::json j = {{"environment", {{"outer", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}}},
                            {"density", density},
                            {"robots", {{"positions", {{0.2, 0.2}, {0.8, 0.8}}}}},
                            {"seed", 1}};
  return parse_scenario(j, "square.json", ".");
}
}  // namespace

TEST_CASE("the colour bar's ticks run from 0 to the density's maximum", "[map_view]") {
  const MapView view(
      square_with({{"type", "gaussian_mixture"},
                   {"components", {{{"mean", {0.5, 0.5}}, {"sigma", 0.2}, {"weight", 3.0}}}}}));
  const std::vector<double> ticks = view.colour_bar_ticks();
  REQUIRE(ticks.size() >= 3);
  CHECK(ticks.front() == 0.0);
  CHECK(ticks.back() <= 3.0);
  CHECK(ticks.back() > 1.5);
}

TEST_CASE("a peak the raster misses gives one tick, not a loop without end", "[map_view]") {
  // σ = 1 µm: no pixel of the map lands within reach of the bump, so the map's maximum is 0.
  const MapView view(square_with(
      {{"type", "gaussian_mixture"},
       {"components", {{{"mean", {0.50031, 0.50077}}, {"sigma", 1e-6}, {"weight", 1.0}}}}}));
  CHECK(view.colour_bar_ticks() == std::vector<double>{0.0});
  CHECK(view.colour_bar_width(10.0) > 0);
}
