#include "analysis/figures/layers.hpp"

#include <array>
#include <stdexcept>

namespace covsim {

namespace {
constexpr std::array<LayerInfo, static_cast<std::size_t>(Layer::count_)> kLayers = {{
    {Layer::obstacles, "obstacles", "obstacles and the outside of Ω (grey), and Ω's boundary"},
    {Layer::density, "density", "the density as a colour map, with its colour bar"},
    {Layer::cells, "cells", "the virtual generators' partition (blue)"},
    {Layer::real_cells, "real-cells", "the real positions' partition (red, dashed)"},
    {Layer::paths, "paths", "each robot's path in its colour, from its start (hollow circle)"},
    {Layer::virtual_paths, "virtual-paths", "each virtual generator's path (thin, dashed)"},
    {Layer::generators, "generators", "the virtual generators (squares)"},
    {Layer::targets, "targets", "virtual targets (crosses), projected real targets (yellow)"},
    {Layer::robots, "robots", "the robots (filled circles)"},
    {Layer::ids, "ids", "each robot's ID beside it"},
    {Layer::axes, "axes", "ticks and labels in metres, and a scale bar"},
    {Layer::legend, "legend", "what each mark means"},
    {Layer::title, "title", "the scenario's name and the outcome (a video: its clock)"},
}};

// The table lists the layers in the enum's order, so a layer is its own index.
constexpr bool in_order() {
  for (std::size_t i = 0; i < kLayers.size(); ++i)
    if (static_cast<std::size_t>(kLayers[i].layer) != i) return false;
  return true;
}
static_assert(in_order());

const LayerInfo* named(std::string_view name) {
  for (const LayerInfo& l : kLayers)
    if (l.name == name) return &l;
  return nullptr;
}
}  // namespace

std::span<const LayerInfo> layer_table() {
  return kLayers;
}

std::string layer_names() {
  std::string out;
  for (const LayerInfo& l : kLayers)
    out += (out.empty() ? "" : ", ") + std::string(l.name);
  return out;
}

Layers Layers::all() {
  Layers out;
  out.bits_.set();
  return out;
}

Layers& Layers::add(Layer l) {
  bits_.set(static_cast<std::size_t>(l));
  return *this;
}

Layers& Layers::remove(Layer l) {
  bits_.reset(static_cast<std::size_t>(l));
  return *this;
}

Layers parse_layers(std::string_view text) {
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument(what + " (the layers: all, " + layer_names() +
                                "; -NAME takes one away)");
  };
  Layers out;
  for (std::size_t start = 0, k = 0; start <= text.size(); ++k) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string_view item = text.substr(start, comma - start);
    start = comma + 1;
    const bool minus = !item.empty() && item.front() == '-';
    if (minus) item.remove_prefix(1);
    if (minus && k == 0) out = Layers::all();
    if (item == "all") {
      if (minus) fail("\"-all\" leaves nothing to draw");
      out = Layers::all();
      continue;
    }
    const LayerInfo* l = named(item);
    if (l == nullptr)
      fail(item.empty() ? "an empty layer name" : "unknown layer \"" + std::string(item) + "\"");
    minus ? out.remove(l->layer) : out.add(l->layer);
  }
  if (out.empty()) fail("no layer left to draw");
  return out;
}

}  // namespace covsim
