#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scenarios/input_file.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_description.hpp"
#include "scenarios/scenario_error.hpp"
#include "scenarios/yaml_reader.hpp"

using namespace covsim;
namespace fs = std::filesystem;

namespace {
const fs::path kScenarios = fs::path(COVSIM_SOURCE_DIR) / "scenarios";

fs::path write_yaml(const std::string& name, const std::string& text) {
  // One folder per process: ctest runs test cases in parallel.
  const fs::path dir =
      fs::temp_directory_path() / ("covsim-yaml-tests-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The message of the ScenarioError that loading `text` as bad.yaml raises.
std::string yaml_error(const std::string& text) {
  const fs::path f = write_yaml("bad.yaml", text);
  try {
    load_scenario(f);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  FAIL("accepted: " << text);
  return "";
}

const std::string kYamlSquare = R"(environment:
  outer: [[0, 0], [4, 0], [4, 4], [0, 4]]
density: {type: uniform}
)";
}  // namespace

TEST_CASE("a YAML scenario reads to the JSON of its twin, number for number", "[scenario][yaml]") {
  const InputFile yaml = read_input(kScenarios / "u_shape.yaml");
  const nlohmann::json json = read_input_file(kScenarios / "u_shape.json");
  CHECK(yaml.json.dump() == json.dump());  // dump tells 1 from 1.0 and every bit of a double
  CHECK(!yaml.places.empty());
  CHECK(describe_scenario(load_scenario(kScenarios / "u_shape.yaml")).dump() ==
        describe_scenario(load_scenario(kScenarios / "u_shape.json")).dump());
  // The same value and kind as parse_json gives the same digits: unsigned, signed, a double
  // where 64 bits overflow, correctly rounded doubles, and 0 below a double's least.
  for (const char* number : {"0",
                             "1",
                             "-1",
                             "-0",
                             "18446744073709551615",
                             "18446744073709551616",
                             "-9223372036854775808",
                             "-9223372036854775809",
                             "0.1",
                             "-0.0",
                             "1e23",
                             "1E5",
                             "-2.5e-3",
                             "0.30000000000000004",
                             "9007199254740993",
                             "123456789012345678901234567890",
                             "2.2250738585072011e-308",
                             "4.9e-324",
                             "2e-324",
                             "1e-400",
                             "-1e-400",
                             "1.7976931348623157e308",
                             "0.000000000000000000000000000001e-300"}) {
    INFO(number);
    const std::string text = std::string("[") + number + "]";
    const nlohmann::json j = parse_json(text, "j");
    const nlohmann::json y = parse_yaml(text, "y").json;
    CHECK(y.dump() == j.dump());
    CHECK(y[0].type() == j[0].type());
  }
}

TEST_CASE("YAML scalars follow the core schema", "[scenario][yaml]") {
  const nlohmann::json j = parse_yaml(R"(# a comment
quoted: '1'
double_quoted: "true"
integer: 1
negative: -2
hex: 0x1f
octal: 0o17
float: 1.5
exponent: 1e3
dot: .5
plus: +4
leading_zeros: 007
yes_word: yes
off_word: off
t: true
f: False
n1: null
n2: ~
n3:
word: tangent_bug
block: |
  two
  lines
str_tag: !!str 12
float_tag: !!float 1
flow: {a: [1, 'b'], "c": {}}
)",
                                      "t.yaml")
                               .json;
  CHECK(j["quoted"] == "1");
  CHECK(j["double_quoted"] == "true");
  CHECK(j["integer"].is_number_unsigned());
  CHECK(j["integer"] == 1);
  CHECK(j["negative"].is_number_integer());
  CHECK(j["negative"] == -2);
  CHECK(j["hex"] == 31);
  CHECK(j["octal"] == 15);
  CHECK(j["float"].is_number_float());
  CHECK(j["exponent"] == 1000.0);
  CHECK(j["exponent"].is_number_float());
  CHECK(j["dot"] == 0.5);
  CHECK(j["plus"] == 4);
  CHECK(j["leading_zeros"] == 7);
  CHECK(j["yes_word"] == "yes");  // YAML 1.1's booleans are strings in 1.2
  CHECK(j["off_word"] == "off");
  CHECK(j["t"] == true);
  CHECK(j["f"] == false);
  CHECK(j["n1"].is_null());
  CHECK(j["n2"].is_null());
  CHECK(j["n3"].is_null());
  CHECK(j["word"] == "tangent_bug");
  CHECK(j["block"] == "two\nlines\n");
  CHECK(j["str_tag"] == "12");
  CHECK(j["float_tag"].is_number_float());
  CHECK(j["flow"] == nlohmann::json::parse(R"({"a": [1, "b"], "c": {}})"));
  // A JSON document is YAML too.
  CHECK(parse_yaml(R"({"x": [1, 2.5, "s", null, true]})", "j.yaml").json ==
        nlohmann::json::parse(R"({"x": [1, 2.5, "s", null, true]})"));
}

TEST_CASE("YAML errors name the file, the line and column and the JSON path", "[scenario][yaml]") {
  // Found while reading: malformed YAML, a duplicate key (at its object), nesting, .nan.
  CHECK_THAT(yaml_error(kYamlSquare + "robots: {positions: [[0.5, 0.5]\nseed: 1\n"),
             Catch::Matches(".*bad\\.yaml:\\d+:\\d+: malformed YAML: .*"));
  CHECK_THAT(yaml_error(kYamlSquare + "seed: 1\nseed: 2\n"),
             Catch::EndsWith("bad.yaml:5:1: $: duplicate key \"seed\" (each key once)"));
  CHECK_THAT(yaml_error(kYamlSquare + "robots:\n  count: 2\n  count: 3\n"),
             Catch::EndsWith("bad.yaml:6:3: $.robots: duplicate key \"count\" (each key once)"));
  CHECK_THAT(yaml_error(std::string(300, '[') + std::string(300, ']')),
             Catch::Contains("bad.yaml:1:257: $[0][0][0]") &&
                 Catch::EndsWith("YAML nested deeper than 256 levels"));
  CHECK_NOTHROW(parse_yaml(std::string(200, '[') + std::string(200, ']'), "nest"));
  CHECK_THAT(yaml_error(kYamlSquare + "sensor:\n  range: .nan\n"),
             Catch::EndsWith("bad.yaml:5:10: $.sensor.range: expected a finite number, found "
                             ".nan (JSON has no infinity or NaN either)"));
  CHECK_THAT(yaml_error(kYamlSquare + "sensor: {range: -.inf}\n"),
             Catch::Contains("bad.yaml:4:17: $.sensor.range: expected a finite number"));
  CHECK_THAT(yaml_error(kYamlSquare + "sensor: {range: 1e999}\n"),
             Catch::EndsWith("bad.yaml:4:17: $.sensor.range: the number 1e999 is out of a "
                             "double's range (about ±1.8e308)"));
  // Found after reading, at a JSON path: the place of the value (or of the key above a
  // block), or of the nearest enclosing value the file has.
  CHECK_THAT(yaml_error(kYamlSquare + "extra: 1\n"),
             Catch::Contains("bad.yaml:4:8: $.extra: unknown key \"extra\" (expected one of: "));
  CHECK_THAT(yaml_error(kYamlSquare + "sensor:\n  noise:\n    sd: 1\n"),
             Catch::Contains("bad.yaml:6:9: $.sensor.noise.sd: unknown key"));
  CHECK_THAT(yaml_error(kYamlSquare + "seed: '7'\n"),
             Catch::EndsWith("bad.yaml:4:7: $.seed: expected a non-negative integer, found a "
                             "string"));
  CHECK_THAT(yaml_error(kYamlSquare + "network:\n  loss: {model: bernoulli}\n"),
             Catch::EndsWith("bad.yaml:5:9: $.network.loss: missing required key \"p\""));
  CHECK_THAT(yaml_error("environment:\n  outer:\n    - [0, 0]\n    - [1, 0]\n    - [1, x]\n" +
                        std::string("density: {type: uniform}\n")),
             Catch::EndsWith("bad.yaml:5:11: $.environment.outer[2][1]: expected a number, "
                             "found a string"));
  CHECK_THAT(yaml_error("environment:\n  outer:\n    - [0, 0]\n    - [2, 2]\n    - [2, 0]\n"
                        "    - [0, 2]\ndensity: {type: uniform}\n"),
             Catch::Contains("bad.yaml:2:3: $.environment.outer: outer ring: is "
                             "self-intersecting"));
  CHECK_THAT(yaml_error("density: {type: uniform}\n"),
             Catch::EndsWith("bad.yaml:1:1: $: missing required key \"environment\""));
  // What JSON cannot say is refused: anchors and aliases, merge keys, other tags, keys that
  // are not strings, a second document; and an empty file holds no scenario.
  CHECK_THAT(yaml_error(kYamlSquare + "robots: {positions: &p [[1, 1]]}\n"),
             Catch::Contains("bad.yaml:4:21: $.robots.positions: anchors (&p) and aliases are "
                             "not read"));
  CHECK_THAT(yaml_error(kYamlSquare + "a: &x 1\nb: *x\n"),
             Catch::Contains("bad.yaml:4:4: $.a: anchors (&x)"));
  CHECK_THAT(yaml_error(kYamlSquare + "robots:\n  <<: {count: 2}\n"),
             Catch::Contains("bad.yaml:5:3: $.robots: merge keys (<<) are not read"));
  CHECK_THAT(yaml_error(kYamlSquare + "seed: !custom 1\n"),
             Catch::Contains("bad.yaml:4:7: $.seed: the tag !custom is not read"));
  CHECK_THAT(yaml_error(kYamlSquare + "seed: !!int x\n"),
             Catch::Contains("bad.yaml:4:7: $.seed: \"x\" is not a !!int"));
  CHECK_THAT(yaml_error(kYamlSquare + "? [a, b]\n: 1\n"),
             Catch::Contains("bad.yaml:4:3: $: a key is a string, not a sequence"));
  CHECK_THAT(yaml_error(kYamlSquare + "---\nseed: 1\n"),
             Catch::EndsWith("bad.yaml:4:1: a second YAML document (a file holds one)"));
  CHECK_THAT(yaml_error(kYamlSquare + "planner: {type: \"tangent\xff\"}\n"),
             Catch::EndsWith("bad.yaml:4:17: $.planner.type: a scalar that is not UTF-8 (the file "
                             "is read as UTF-8)"));
  CHECK_THAT(yaml_error(kYamlSquare + "\xed\xa0\x80: 1\n"),  // a surrogate
             Catch::EndsWith("bad.yaml:4:1: $: a scalar that is not UTF-8 (the file is read as "
                             "UTF-8)"));
  CHECK(parse_yaml("s: \"Ω \xf0\x9f\x98\x80\"", "u.yaml").json["s"] == "Ω \xf0\x9f\x98\x80");
  CHECK_THAT(yaml_error("# nothing but a comment\n"),
             Catch::EndsWith("bad.yaml:1:1: malformed YAML: no document (the file is empty)"));
  // The reader picks YAML by the name alone.
  CHECK(is_yaml_file("a.yml"));
  CHECK(is_yaml_file("dir.json/a.yaml"));
  CHECK_FALSE(is_yaml_file("a.yaml.json"));
  const fs::path dir = write_yaml("x.yaml", "{}").parent_path() / "a-folder.yaml";
  fs::create_directories(dir);
  CHECK_THROWS_WITH(load_scenario(dir), Catch::Contains("is a directory, not a YAML file"));
}

TEST_CASE("an error's place falls back to the nearest value the file has", "[scenario][yaml]") {
  const InputFile in = parse_yaml("a:\n  b: [1, 2]\n", "f.yaml");
  CHECK(in.place_of("$.a.b[1]").line == 2);
  CHECK(in.place_of("$.a.b[1]").column == 10);
  CHECK(in.place_of("$.a.b[7].c").column == 6);  // the array
  CHECK(in.place_of("$.a.x").line == 1);         // the key above a block
  CHECK_FALSE(in.place_of("other").known());
  // Errors of other files, and errors that already have a place, are left as they are.
  const ScenarioError other("g.yaml", "$.a", "wrong");
  CHECK(std::string(in.located(other).what()) == "g.yaml: $.a: wrong");
  const ScenarioError own("f.yaml", "$.a.b", "wrong");
  CHECK(std::string(in.located(own).what()) == "f.yaml:2:6: $.a.b: wrong");
  CHECK(in.located(own).place().line == 2);
  CHECK(std::string(in.located(in.located(own)).what()) == "f.yaml:2:6: $.a.b: wrong");
}
