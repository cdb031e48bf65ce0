#include "analysis/svg_canvas.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace covsim {

SvgCanvas::SvgCanvas(const Box& world, double width, double margin)
    : world_(world), width_(width), margin_(margin) {
  const Vec2 size = world.size();
  scale_ = (width - 2 * margin) / std::max(size.x, 1e-12);
  height_ = size.y * scale_ + 2 * margin;
}

Vec2 SvgCanvas::to_px(Vec2 w) const {
  return {margin_ + (w.x - world_.lo.x) * scale_, height_ - margin_ - (w.y - world_.lo.y) * scale_};
}

std::string SvgCanvas::path_data(const std::vector<std::vector<Vec2>>& rings) const {
  std::string d;
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 p = to_px(ring[i]);
      d += fmt::format("{}{:.2f},{:.2f}", i == 0 ? "M" : "L", p.x, p.y);
    }
    d += "Z";
  }
  return d;
}

void SvgCanvas::rings(const std::vector<std::vector<Vec2>>& rs, const std::string& style) {
  body_ +=
      fmt::format("<path fill-rule=\"evenodd\" d=\"{}\" style=\"{}\"/>\n", path_data(rs), style);
}

void SvgCanvas::polyline(const std::vector<Vec2>& pts, const std::string& style) {
  if (pts.size() < 2) return;
  std::string d;
  for (Vec2 w : pts) {
    const Vec2 p = to_px(w);
    d += fmt::format("{:.2f},{:.2f} ", p.x, p.y);
  }
  body_ += fmt::format("<polyline fill=\"none\" points=\"{}\" style=\"{}\"/>\n", d, style);
}

void SvgCanvas::circle(Vec2 c, double r, const std::string& style) {
  const Vec2 p = to_px(c);
  body_ += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" style=\"{}\"/>\n", p.x,
                       p.y, r, style);
}

void SvgCanvas::cross(Vec2 c, double h, const std::string& style) {
  const Vec2 p = to_px(c);
  body_ += fmt::format(
      "<path d=\"M{:.2f},{:.2f}L{:.2f},{:.2f}M{:.2f},{:.2f}L{:.2f},{:.2f}\" style=\"{}\"/>\n",
      p.x - h, p.y - h, p.x + h, p.y + h, p.x - h, p.y + h, p.x + h, p.y - h, style);
}

void SvgCanvas::text(Vec2 p, const std::string& s, const std::string& style) {
  body_ +=
      fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" style=\"{}\">{}</text>\n", p.x, p.y, style, s);
}

void SvgCanvas::clip_path(const std::string& id, const std::vector<std::vector<Vec2>>& rs) {
  defs_ += fmt::format("<clipPath id=\"{}\"><path clip-rule=\"evenodd\" d=\"{}\"/></clipPath>\n",
                       id, path_data(rs));
}

std::string SvgCanvas::str() const {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 "
      "{:.0f} {:.0f}\" "
      "font-family=\"sans-serif\">\n<defs>\n{}</defs>\n{}</svg>\n",
      width_, height_, width_, height_, defs_, body_);
}

}  // namespace covsim
