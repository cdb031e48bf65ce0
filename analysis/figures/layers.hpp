#pragma once
// What a scene or a video frame draws, layer by layer, each named once here: the option
// parser, its help and the check of docs/outputs.md read this table.
#include <bitset>
#include <span>
#include <string>
#include <string_view>

namespace covsim {

enum class Layer {
  obstacles,      // Ω's obstacles and what lies outside it, grey, and ∂Ω
  density,        // the density as a colour map, with its colour bar
  cells,          // the virtual generators' partition
  real_cells,     // the real positions' partition
  paths,          // each robot's path, from its start
  virtual_paths,  // each virtual generator's path
  generators,     // the virtual generators where they stand
  targets,        // virtual targets, and real targets projected onto Ω
  robots,         // the robots where they stand
  ids,            // each robot's ID beside it
  axes,           // ticks in metres and a scale bar
  legend,         // what each mark means
  title,          // the scenario's name and the outcome, or the video's clock
  count_
};

struct LayerInfo {
  Layer layer;
  std::string_view name;  // as --layers spells it
  std::string_view what;
};
std::span<const LayerInfo> layer_table();
// "obstacles, density, ...": every name, in the table's order.
std::string layer_names();

class Layers {
 public:
  static Layers all();
  static Layers none() { return Layers{}; }
  bool has(Layer l) const { return bits_.test(static_cast<std::size_t>(l)); }
  Layers& add(Layer l);
  Layers& remove(Layer l);
  bool empty() const { return bits_.none(); }
  bool operator==(const Layers&) const = default;

 private:
  std::bitset<static_cast<std::size_t>(Layer::count_)> bits_;
};

// A comma list of layer names (only these are drawn), "all" for every layer, and names
// after a minus taken away ("all,-virtual-paths"; a list that starts with a removal starts
// from all). Throws std::invalid_argument naming what is wrong and the layers there are.
Layers parse_layers(std::string_view text);

}  // namespace covsim
