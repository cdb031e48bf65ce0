// readable_json: a vertex per line, and the same value back.
#include <catch2/catch.hpp>

#include "scenarios/readable_json.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_description.hpp"
#include "scenarios/scenario_override.hpp"

using namespace covsim;

TEST_CASE("readable JSON puts a point on a line and parses back to the same value", "[scenario]") {
  const nlohmann::json j = {{"outer", {{0.0, 0.0}, {1.0, 0.0}, {0.35, 1.0}}},
                            {"holes", nlohmann::json::array()},
                            {"known", "full"},
                            {"sections", {{{"type", "a"}}, {{"type", "b"}, {"p", nullptr}}}},
                            {"empty", nlohmann::json::object()},
                            {"x", 0.1}};
  const std::string text = readable_json(j);
  CHECK(text ==
        "{\n"
        "  \"empty\": {},\n"
        "  \"holes\": [],\n"
        "  \"known\": \"full\",\n"
        "  \"outer\": [\n"
        "    [0.0, 0.0],\n"
        "    [1.0, 0.0],\n"
        "    [0.35, 1.0]\n"
        "  ],\n"
        "  \"sections\": [\n"
        "    {\n"
        "      \"type\": \"a\"\n"
        "    },\n"
        "    {\n"
        "      \"p\": null,\n"
        "      \"type\": \"b\"\n"
        "    }\n"
        "  ],\n"
        "  \"x\": 0.1\n"
        "}");
  CHECK(nlohmann::json::parse(text) == j);
  // A whole scenario as described, in its order, and back (office: many walls).
  const nlohmann::ordered_json d = describe_scenario(
      load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/office.json", {}));
  const std::string described = readable_json(d);
  CHECK(nlohmann::ordered_json::parse(described) == d);
  CHECK(4 * described.size() < 3 * d.dump(2).size());
}
