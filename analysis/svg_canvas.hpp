#pragma once
// A small SVG writer with a world-to-picture transform (y up in the world, down in SVG).
#include <string>
#include <vector>

#include "core/geometry/vec2.hpp"

namespace covsim {

class SvgCanvas {
 public:
  // A picture `width` pixels wide showing `world` (aspect ratio kept), with a margin.
  SvgCanvas(const Box& world, double width, double margin);
  double width() const { return width_; }
  double height() const { return height_; }
  Vec2 to_px(Vec2 w) const;
  double scale() const { return scale_; }

  void raw(const std::string& svg) { body_ += svg; }
  // A path of several closed rings (even-odd fill), e.g. a polygon with holes.
  void rings(const std::vector<std::vector<Vec2>>& rings, const std::string& style);
  void polyline(const std::vector<Vec2>& pts, const std::string& style);
  void circle(Vec2 c, double radius_px, const std::string& style);
  void cross(Vec2 c, double half_px, const std::string& style);
  void text(Vec2 px, const std::string& s, const std::string& style);  // at picture coordinates
  // Defines a clip path from rings; later elements use style "clip-path:url(#id)".
  void clip_path(const std::string& id, const std::vector<std::vector<Vec2>>& rings);
  std::string str() const;

 private:
  std::string path_data(const std::vector<std::vector<Vec2>>& rings) const;
  Box world_;
  double width_, height_, margin_, scale_;
  std::string defs_, body_;
};

}  // namespace covsim
