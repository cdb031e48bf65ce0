#pragma once
// A point as the records write it: the JSON array [x, y].
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/vec2.hpp"

namespace covsim {

inline nlohmann::ordered_json point_json(Vec2 p) {
  return nlohmann::ordered_json::array({p.x, p.y});
}

// Throws std::invalid_argument unless the value is [x, y].
inline Vec2 json_point(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 2) throw std::invalid_argument("expected [x, y]");
  return {j.at(0).get<double>(), j.at(1).get<double>()};
}

}  // namespace covsim
