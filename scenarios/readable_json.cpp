#include "scenarios/readable_json.hpp"

#include <algorithm>

namespace covsim {

namespace {

template <class Json>
void write(const Json& j, int depth, std::string& out) {
  const auto pad = [&](int d) { out.append(static_cast<std::size_t>(2 * d), ' '); };
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!first) out += ",\n";
      first = false;
      pad(depth + 1);
      out += Json(it.key()).dump() + ": ";
      write(*it, depth + 1, out);
    }
    out += "\n";
    pad(depth);
    out += "}";
  } else if (j.is_array() && !j.empty()) {
    const bool plain =
        std::none_of(j.begin(), j.end(), [](const Json& e) { return e.is_structured(); });
    if (plain) {
      out += "[";
      for (std::size_t k = 0; k < j.size(); ++k)
        out += (k == 0 ? "" : ", ") + j[k].dump();
      out += "]";
      return;
    }
    out += "[\n";
    for (std::size_t k = 0; k < j.size(); ++k) {
      if (k > 0) out += ",\n";
      pad(depth + 1);
      write(j[k], depth + 1, out);
    }
    out += "\n";
    pad(depth);
    out += "]";
  } else {
    out += j.dump();  // a scalar, {} or []
  }
}

template <class Json>
std::string text(const Json& j) {
  std::string out;
  write(j, 0, out);
  return out;
}

}  // namespace

std::string readable_json(const nlohmann::json& j) {
  return text(j);
}
std::string readable_json(const nlohmann::ordered_json& j) {
  return text(j);
}

}  // namespace covsim
