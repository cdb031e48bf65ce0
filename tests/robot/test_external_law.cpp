// Targets set from outside (robot/external_law): the driver's targets, the robot's own
// point (its position as it knows it) until it sets one; never at rest.
#include <catch2/catch.hpp>

#include "robot/coverage_law_registry.hpp"
#include "robot/external_law.hpp"
#include "tests/robot/law_cases.hpp"

using namespace covsim;
using namespace covsim::test;

TEST_CASE("the external law returns what the driver set, else the robot's position", "[law]") {
  const Environment env = unit_square();
  const std::vector<Vec2> p{{0.2, 0.3}, {0.8, 0.3}};
  ExternalLaw law;
  const Robot r0 = robot_at(0, p[0]), r1 = robot_at(1, p[1]);
  CHECK(law.target(r0, own(p, 0, Generators::positions)) == p[0]);
  law.set_target(1, {0.9, 0.9});
  CHECK(law.target(r1, own(p, 1, Generators::positions)) == Vec2{0.9, 0.9});
  CHECK(law.target(r0, own(p, 0, Generators::positions)) == p[0]);
  law.set_target(1, {0.1, 0.1});  // the latest wins
  CHECK(law.target(r1, own(p, 1, Generators::positions)) == Vec2{0.1, 0.1});
  // Where the robot is as it knows it (an estimate, with a localization): its own point.
  const std::vector<Vec2> estimated{{0.21, 0.29}, {0.8, 0.3}};
  CHECK(law.target(r0, own(estimated, 0, Generators::virtual_generators)) == estimated[0]);
  CHECK_FALSE(law.at_rest(r1, Tolerances{1.0, 1.0}));  // only the driver knows when it is done
  CHECK_FALSE(law.moves_virtual_generators());
}

TEST_CASE("the registry's external entry builds that law and is not autonomous", "[law]") {
  const Environment env = unit_square();
  const UniformDensity density;
  const CellIntegrator integrator(env, density);
  LawConfig c;
  c.type = "external";
  std::unique_ptr<CoverageLaw> law = make_coverage_law(c, LawContext{env, density, integrator});
  auto* external = dynamic_cast<ExternalLaw*>(law.get());
  REQUIRE(external != nullptr);
  external->set_target(0, {0.4, 0.6});
  const std::vector<Vec2> p{{0.5, 0.5}};
  CHECK(law->target(robot_at(0, p[0]), own(p, 0, Generators::positions)) == Vec2{0.4, 0.6});
  CHECK_FALSE(coverage_law_registry().at("external").autonomous);
}
