#pragma once
// One registry per extension point (planners, coverage laws, loss models, delay models,
// densities): an explicit table of components, each with its name, a one-line description,
// its parameter schema and its factory. The built-in components are listed once, in the
// table that creates the registry (static libraries drop self-registering objects nothing
// references, so there is no static self-registration); a user's program or a plugin adds
// its own with add() before any run starts. Nothing else in covsim lists component names:
// the loader, `covsim list`, sweeps and scripts ask the registry.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/param_schema.hpp"

namespace covsim {

struct ComponentInfo {
  std::string name;
  std::string description;  // one line
  ParamSchema params;
};

// A component whose factory has the signature the extension point needs.
template <class Make>
struct Component : ComponentInfo {
  Make make;
};

template <class Entry>
class Registry {
 public:
  Registry(std::string kind, std::vector<Entry> entries) : kind_(std::move(kind)) {
    for (Entry& e : entries)
      add(std::move(e));
  }
  // What the registry holds, in words ("planner", "coverage law").
  const std::string& kind() const { return kind_; }
  // Throws std::invalid_argument for an empty or taken name, or no factory.
  void add(Entry e) {
    if (e.name.empty()) throw std::invalid_argument(kind_ + ": a component needs a name");
    if (find(e.name) != nullptr)
      throw std::invalid_argument(fmt::format("{} \"{}\" is registered already", kind_, e.name));
    if (!e.make)
      throw std::invalid_argument(fmt::format("{} \"{}\" has no factory", kind_, e.name));
    entries_.push_back(std::move(e));
  }
  // Takes a component out (a Python-defined one when its interpreter ends); false if absent.
  bool remove(std::string_view name) {
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
      if (it->name == name) {
        entries_.erase(it);
        return true;
      }
    }
    return false;
  }
  const Entry* find(std::string_view name) const {
    for (const Entry& e : entries_) {
      if (e.name == name) return &e;
    }
    return nullptr;
  }
  // Throws std::invalid_argument naming the registered ones.
  const Entry& at(std::string_view name) const {
    if (const Entry* e = find(name)) return *e;
    throw std::invalid_argument(
        fmt::format("unknown {} \"{}\" (registered: {})", kind_, name, fmt::join(names(), ", ")));
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_)
      out.push_back(e.name);
    return out;
  }
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::string kind_;
  std::vector<Entry> entries_;
};

}  // namespace covsim
