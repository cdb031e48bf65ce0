// `covsim random-env --seed N [--out FILE]`: a random polygonal environment with holes and
// robots, as a scenario file (stdout without --out).
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/scenario_options.hpp"
#include "io/atomic_file.hpp"
#include "scenarios/random_environment.hpp"
#include "scenarios/scenario.hpp"

namespace covsim::app {

void add_random_env_command(CLI::App& app) {
  auto spec = std::make_shared<RandomEnvironmentSpec>();
  auto out = std::make_shared<std::string>();
  auto seed = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "random-env", "Write a random polygonal environment with holes and robots as a scenario");
  cmd->add_option("--seed", *seed, "Seed (0 to 2^64 - 1): the same seed gives the same scenario")
      ->required();
  cmd->add_option("--out", *out, "Scenario file to write (default: stdout)");
  cmd->add_option("--size", spec->size, "Side of the square the environment lies in [m]")
      ->capture_default_str();
  cmd->add_option("--vertices", spec->outer_vertices, "Vertices of the outer ring")
      ->capture_default_str();
  cmd->add_option("--holes", spec->holes, "Holes (at most; fewer if they do not fit)")
      ->capture_default_str();
  cmd->add_option("--robots", spec->robots, "Robots")->capture_default_str();
  cmd->callback([spec, out, seed] {
    spec->seed = parse_seed(*seed);
    nlohmann::ordered_json scenario;
    try {
      scenario = random_environment(*spec);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("random-env: ") + e.what());
    }
    // Holes are placed at random and kept only where they fit: say when fewer did.
    const std::size_t placed = scenario["environment"]["holes"].size();
    if (placed < spec->holes) {
      std::cerr << fmt::format(
          "random-env: placed {} of the {} holes asked for; the others did not fit in the {} m "
          "square (a larger --size makes room)\n",
          placed, spec->holes, spec->size);
    }
    const std::string text = scenario.dump(2) + "\n";
    // What is written must load as a scenario.
    parse_scenario(nlohmann::json::parse(text), "random-env", ".");
    if (out->empty()) {
      std::cout << text;
      return;
    }
    AtomicFile f(*out);
    f.stream() << text;
    f.commit();
  });
}

}  // namespace covsim::app
