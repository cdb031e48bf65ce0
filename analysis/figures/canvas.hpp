#pragma once
// One drawing path for every figure: a cairo surface in SVG, PDF or PNG (or a raw raster
// for video frames), with the few primitives covsim's figures use. Coordinates are picture
// points, y down; figures map the world onto them through an Axes.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/figures/figure_size.hpp"
#include "core/vec2.hpp"

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;

namespace covsim {

enum class FigureFormat { svg, pdf, png };
// "svg", "pdf" or "png"; nullopt otherwise.
std::optional<FigureFormat> parse_figure_format(std::string_view name);
std::string_view extension(FigureFormat f);  // "svg", ...

// What file a figure becomes.
struct FigureFile {
  FigureFormat format = FigureFormat::svg;
  int png_width = 0;  // a PNG's width in pixels; 0: two pixels per point
  FigureSize size = default_figure_size();
};

struct Colour {
  double r = 0, g = 0, b = 0, a = 1;
  static Colour hex(std::uint32_t rgb, double alpha = 1.0);
};

struct Stroke {
  Colour colour;
  double width = 1.0;
  std::vector<double> dash = {};  // on, off, ... in points; empty: solid
};

enum class Align { left, centre, right };

// The advance of a line of text in DejaVu Sans at `size` points, as every canvas lays it out
// (unhinted metrics, whatever the surface), for laying out a figure before drawing it.
double text_width(std::string_view s, double size, bool bold = false);
// `s` broken at spaces into lines no wider than `width` where it can be (a word wider than
// `width` keeps a line to itself).
std::vector<std::string> wrap_text(std::string_view s, double size, double width);

// An RGBA image, row 0 at the top, drawn scaled into a rectangle (a density map, say).
struct Image {
  int width = 0, height = 0;
  std::vector<Colour> pixels;  // width * height, row-major
};

class Canvas {
 public:
  // A figure of width × height points (a PNG: scaled to its width in pixels).
  Canvas(const FigureFile& file, double width, double height);
  // A raster of width × height pixels for video frames (BGRA, premultiplied).
  static Canvas raster(int width, int height);
  Canvas(Canvas&&) noexcept;
  Canvas& operator=(Canvas&&) = delete;
  ~Canvas();

  double width() const { return width_; }
  double height() const { return height_; }

  void fill(const std::vector<std::vector<Vec2>>& rings, Colour c);           // even-odd
  void stroke(const std::vector<std::vector<Vec2>>& rings, const Stroke& s);  // closed
  void polyline(const std::vector<Vec2>& points, const Stroke& s);
  void line(Vec2 a, Vec2 b, const Stroke& s) { polyline({a, b}, s); }
  void rectangle(Vec2 lo, Vec2 hi, std::optional<Colour> fill, std::optional<Stroke> s = {});
  void circle(Vec2 c, double radius, std::optional<Colour> fill, std::optional<Stroke> s = {});
  void square(Vec2 c, double half, std::optional<Colour> fill, std::optional<Stroke> s = {});
  void cross(Vec2 c, double half, const Stroke& s);
  // Text whose baseline starts, centres or ends at p, turned by `degrees` anticlockwise.
  void text(Vec2 p, std::string_view s, double size, Colour c, Align align = Align::left,
            double degrees = 0.0, bool bold = false);
  void image(const Image& img, Vec2 lo, Vec2 hi);  // lo: top-left corner
  // Clips what follows to the rings (even-odd) until the matching pop_clip.
  void push_clip(const std::vector<std::vector<Vec2>>& rings);
  void pop_clip();

  // The finished file's bytes (SVG, PDF or PNG); the canvas is spent afterwards.
  std::string finish();
  // A raster canvas's pixels: height rows of `stride` bytes, BGRA.
  const unsigned char* pixels();
  int stride() const;

 private:
  Canvas() = default;
  void path(const std::vector<std::vector<Vec2>>& rings, bool close);
  void apply(const Stroke& s);
  // Fills and/or strokes the current path, then clears it.
  void paint(std::optional<Colour> fill, const std::optional<Stroke>& s);
  void set(Colour c);
  FigureFormat format_ = FigureFormat::png;
  bool raster_ = false;
  double width_ = 0, height_ = 0;
  std::unique_ptr<std::string> bytes_;  // where a vector surface writes (stable address)
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

}  // namespace covsim
