#include "scenarios/component_reader.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace covsim {

ParamValue read_param(const JsonValue& v, const ParamSpec& s) {
  if (v.is_null()) {
    if (s.nullable) return std::monostate{};
    v.fail(check_param(s, std::monostate{}));
  }
  ParamValue out;
  switch (s.kind) {
    case ParamKind::number:
      out = v.number();
      break;
    case ParamKind::integer:
      out = v.unsigned_integer();
      break;
    case ParamKind::boolean:
      out = v.boolean();
      break;
    case ParamKind::choice:
      out = v.one_of(s.choices);
      break;
    case ParamKind::text:
      out = v.string();
      break;
    case ParamKind::point:
      out = v.point();
      break;
    case ParamKind::extent: {
      if (v.size() != 2) v.fail("expected [[x_min, y_min], [x_max, y_max]]");
      out = Box{v[0].point(), v[1].point()};
      break;
    }
    case ParamKind::objects: {
      ParamObjects list;
      for (std::size_t i = 0; i < v.size(); ++i)
        list.push_back(read_params(v[i], s.fields));
      out = std::move(list);
      break;
    }
  }
  if (const std::string problem = check_param(s, out); !problem.empty()) v.fail(problem);
  return out;
}

namespace {
bool contains(const std::vector<std::string>& list, const std::string& s) {
  return std::find(list.begin(), list.end(), s) != list.end();
}
}  // namespace

Params read_params(const JsonValue& section, const ParamSchema& schema,
                   const std::vector<std::string>& other_keys) {
  std::vector<std::string> allowed = other_keys;
  for (const ParamSpec& s : schema)
    allowed.push_back(s.name);
  section.only_keys(allowed);
  Params p;
  for (const ParamSpec& s : schema) {
    if (auto v = section.find(s.name)) p.set(s.name, read_param(*v, s));
  }
  try {
    return with_defaults(schema, std::move(p));
  } catch (const ParamError& e) {
    section.fail(e.what());
  }
}

nlohmann::ordered_json param_to_json(const ParamValue& value) {
  return std::visit(
      [](const auto& x) -> nlohmann::ordered_json {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, std::monostate>) return nullptr;
        if constexpr (std::is_same_v<T, Vec2>) return {x.x, x.y};
        if constexpr (std::is_same_v<T, Box>) return {{x.lo.x, x.lo.y}, {x.hi.x, x.hi.y}};
        if constexpr (std::is_same_v<T, ParamObjects>) {
          nlohmann::ordered_json a = nlohmann::ordered_json::array();
          for (const Params& o : x)
            a.push_back(params_to_json(o));
          return a;
        }
        if constexpr (!std::is_same_v<T, std::monostate> && !std::is_same_v<T, Vec2> &&
                      !std::is_same_v<T, Box> && !std::is_same_v<T, ParamObjects>)
          return x;
      },
      value);
}

nlohmann::ordered_json params_to_json(const Params& p) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [name, value] : p.values())
    j[name] = param_to_json(value);
  return j;
}

ComponentChoice read_component(const JsonValue& section,
                               const std::vector<const ComponentInfo*>& registered,
                               const std::string& kind, const std::string& type_key,
                               const std::optional<std::string>& default_type,
                               const std::vector<std::string>& section_keys) {
  std::vector<std::string> names;
  for (const ComponentInfo* c : registered)
    names.push_back(c->name);
  ComponentChoice choice;
  if (auto t = section.find(type_key)) {
    choice.type = t->one_of(names);
  } else if (default_type) {
    choice.type = *default_type;
  } else {
    section.at(type_key);  // fails: missing required key
  }
  const ComponentInfo* selected = nullptr;
  for (const ComponentInfo* c : registered) {
    if (c->name == choice.type) selected = c;
  }
  if (selected == nullptr)
    section.fail(fmt::format("no {} \"{}\" is registered", kind, choice.type));
  // Every per-type section is checked against its own type's schema.
  std::optional<JsonValue> own;
  for (const ComponentInfo* c : registered) {
    if (auto sub = section.find(c->name)) {
      read_params(*sub, c->params);
      if (c == selected) own = sub;
    }
  }
  // The section's own keys: the selected type's parameters.
  std::vector<std::string> reserved = names;
  reserved.push_back(type_key);
  reserved.insert(reserved.end(), section_keys.begin(), section_keys.end());
  for (const auto& [key, value] : section.raw().items()) {
    if (contains(reserved, key) || find_param(selected->params, key) != nullptr) continue;
    std::string owners;
    for (const ComponentInfo* c : registered) {
      if (find_param(c->params, key) != nullptr) owners += (owners.empty() ? "" : ", ") + c->name;
    }
    const JsonValue bad = *section.find(key);
    if (!owners.empty()) {
      bad.fail(fmt::format(
          "\"{}\" is not a parameter of {} \"{}\" (it is one of {}: to keep it for runs of "
          "that type, put it in \"{}\": {{...}})",
          key, kind, choice.type, owners, owners.substr(0, owners.find(','))));
    }
    std::string list;
    for (const ParamSpec& s : selected->params)
      list += (list.empty() ? "" : ", ") + s.name;
    bad.fail(fmt::format("unknown key \"{}\" for {} \"{}\" (its parameters: {})", key, kind,
                         choice.type, list.empty() ? "none" : list));
  }
  Params flat;
  for (const ParamSpec& s : selected->params) {
    if (auto v = section.find(s.name)) flat.set(s.name, read_param(*v, s));
  }
  if (own) {
    const Params from_own = read_params(*own, selected->params);
    for (const auto& [name, value] : from_own.values()) {
      // Only what the per-type section sets explicitly, not its defaults.
      if (!own->find(name)) continue;
      if (section.find(name))
        own->at(name).fail(
            fmt::format("\"{}\" is set twice, here and in {}", name, section.path()));
      flat.set(name, value);
    }
  }
  try {
    choice.params = with_defaults(selected->params, std::move(flat));
  } catch (const ParamError& e) {
    section.fail(e.what());
  }
  return choice;
}

void fail_param(const JsonValue& section, const ParamError& e) {
  if (section.raw().is_object()) {
    if (auto v = section.find(e.param())) v->fail(e.what());
  }
  section.fail(fmt::format("{}: {}", e.param(), e.what()));
}

}  // namespace covsim
