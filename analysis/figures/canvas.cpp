#include "analysis/figures/canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace covsim {

std::optional<FigureFormat> parse_figure_format(std::string_view name) {
  if (name == "svg") return FigureFormat::svg;
  if (name == "pdf") return FigureFormat::pdf;
  if (name == "png") return FigureFormat::png;
  return std::nullopt;
}

std::string_view extension(FigureFormat f) {
  switch (f) {
    case FigureFormat::svg:
      return "svg";
    case FigureFormat::pdf:
      return "pdf";
    case FigureFormat::png:
      return "png";
  }
  return "";
}

Colour Colour::hex(std::uint32_t rgb, double alpha) {
  return {((rgb >> 16) & 0xff) / 255.0, ((rgb >> 8) & 0xff) / 255.0, (rgb & 0xff) / 255.0, alpha};
}

namespace {
cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void check(cairo_status_t status, const char* what) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string(what) + ": " + cairo_status_to_string(status));
}

// Unhinted metrics on every surface, so that a layout measured once holds in SVG, PDF, PNG
// and video frames alike.
void set_text_options(cairo_t* cr) {
  cairo_font_options_t* o = cairo_font_options_create();
  cairo_font_options_set_hint_metrics(o, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, o);
  cairo_font_options_destroy(o);
}

void select_font(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double advance(cairo_t* cr, std::string_view s, double size, bool bold) {
  select_font(cr, size, bold);
  cairo_text_extents_t e;
  const std::string text(s);
  cairo_text_extents(cr, text.c_str(), &e);
  return e.x_advance;
}
}  // namespace

double text_width(std::string_view s, double size, bool bold) {
  // One small context per thread to measure with (sweeps draw from worker threads).
  struct Measure {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
    cairo_t* cr = cairo_create(surface);
    Measure() { set_text_options(cr); }
    ~Measure() {
      cairo_destroy(cr);
      cairo_surface_destroy(surface);
    }
  };
  thread_local Measure m;
  return advance(m.cr, s, size, bold);
}

std::vector<std::string> wrap_text(std::string_view s, double size, double width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start < s.size()) {
    const std::size_t space = std::min(s.find(' ', start), s.size());
    const std::string word(s.substr(start, space - start));
    start = space + 1;
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_width(longer, size) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

Canvas::Canvas(const FigureFile& file, double width, double height)
    : format_(file.format),
      width_(width),
      height_(height),
      bytes_(std::make_unique<std::string>()) {
  const FigureFormat format = file.format;
  const double png_scale = file.png_width > 0 ? file.png_width / width : 2.0;
  switch (format) {
    case FigureFormat::svg:
      surface_ = cairo_svg_surface_create_for_stream(append, bytes_.get(), width, height);
      cairo_svg_surface_set_document_unit(surface_, CAIRO_SVG_UNIT_PT);
      break;
    case FigureFormat::pdf:
      surface_ = cairo_pdf_surface_create_for_stream(append, bytes_.get(), width, height);
      // A fixed date keeps the same figure the same file.
      cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_CREATE_DATE,
                                     "2000-01-01T00:00:00Z");
      cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_CREATOR, "covsim");
      break;
    case FigureFormat::png:
      surface_ = cairo_image_surface_create(
          CAIRO_FORMAT_ARGB32,
          file.png_width > 0 ? file.png_width : static_cast<int>(std::lround(width * png_scale)),
          std::max(1, static_cast<int>(std::lround(height * png_scale))));
      break;
  }
  check(cairo_surface_status(surface_), "cairo surface");
  cr_ = cairo_create(surface_);
  set_text_options(cr_);
  if (format == FigureFormat::png) cairo_scale(cr_, png_scale, png_scale);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
}

Canvas Canvas::raster(int width, int height) {
  Canvas c;
  c.raster_ = true;
  c.width_ = width;
  c.height_ = height;
  c.surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  check(cairo_surface_status(c.surface_), "cairo surface");
  c.cr_ = cairo_create(c.surface_);
  set_text_options(c.cr_);
  cairo_set_line_join(c.cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(c.cr_, CAIRO_LINE_CAP_ROUND);
  return c;
}

Canvas::Canvas(Canvas&& o) noexcept
    : format_(o.format_),
      raster_(o.raster_),
      width_(o.width_),
      height_(o.height_),
      bytes_(std::move(o.bytes_)),
      surface_(o.surface_),
      cr_(o.cr_) {
  o.surface_ = nullptr;
  o.cr_ = nullptr;
}

Canvas::~Canvas() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

void Canvas::set(Colour c) {
  cairo_set_source_rgba(cr_, c.r, c.g, c.b, c.a);
}

void Canvas::apply(const Stroke& s) {
  set(s.colour);
  cairo_set_line_width(cr_, s.width);
  cairo_set_dash(cr_, s.dash.empty() ? nullptr : s.dash.data(), static_cast<int>(s.dash.size()),
                 0.0);
}

void Canvas::path(const std::vector<std::vector<Vec2>>& rings, bool close) {
  cairo_new_path(cr_);
  for (const auto& ring : rings) {
    if (ring.empty()) continue;
    cairo_move_to(cr_, ring[0].x, ring[0].y);
    for (std::size_t i = 1; i < ring.size(); ++i)
      cairo_line_to(cr_, ring[i].x, ring[i].y);
    if (close) cairo_close_path(cr_);
  }
}

void Canvas::fill(const std::vector<std::vector<Vec2>>& rings, Colour c) {
  path(rings, true);
  cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_EVEN_ODD);
  set(c);
  cairo_fill(cr_);
}

void Canvas::stroke(const std::vector<std::vector<Vec2>>& rings, const Stroke& s) {
  path(rings, true);
  apply(s);
  cairo_stroke(cr_);
}

void Canvas::polyline(const std::vector<Vec2>& points, const Stroke& s) {
  if (points.size() < 2) return;
  path({points}, false);
  apply(s);
  cairo_stroke(cr_);
}

void Canvas::paint(std::optional<Colour> fill, const std::optional<Stroke>& s) {
  if (fill) {
    set(*fill);
    s ? cairo_fill_preserve(cr_) : cairo_fill(cr_);
  }
  if (s) {
    apply(*s);
    cairo_stroke(cr_);
  }
  cairo_new_path(cr_);
}

void Canvas::rectangle(Vec2 lo, Vec2 hi, std::optional<Colour> fill, std::optional<Stroke> s) {
  cairo_new_path(cr_);
  cairo_rectangle(cr_, lo.x, lo.y, hi.x - lo.x, hi.y - lo.y);
  paint(fill, s);
}

void Canvas::circle(Vec2 c, double radius, std::optional<Colour> fill, std::optional<Stroke> s) {
  cairo_new_path(cr_);
  cairo_arc(cr_, c.x, c.y, radius, 0.0, 2.0 * M_PI);
  cairo_close_path(cr_);
  paint(fill, s);
}

void Canvas::square(Vec2 c, double half, std::optional<Colour> fill, std::optional<Stroke> s) {
  rectangle(c - Vec2{half, half}, c + Vec2{half, half}, fill, s);
}

void Canvas::cross(Vec2 c, double half, const Stroke& s) {
  cairo_new_path(cr_);
  cairo_move_to(cr_, c.x - half, c.y - half);
  cairo_line_to(cr_, c.x + half, c.y + half);
  cairo_move_to(cr_, c.x - half, c.y + half);
  cairo_line_to(cr_, c.x + half, c.y - half);
  apply(s);
  cairo_stroke(cr_);
}

void Canvas::text(Vec2 p, std::string_view s, double size, Colour c, Align align, double degrees,
                  bool bold) {
  const double w = advance(cr_, s, size, bold);  // selects the font too
  cairo_save(cr_);
  cairo_translate(cr_, p.x, p.y);
  cairo_rotate(cr_, -degrees * M_PI / 180.0);
  const double dx = align == Align::left ? 0.0 : align == Align::centre ? -w / 2 : -w;
  cairo_move_to(cr_, dx, 0.0);
  set(c);
  const std::string text(s);
  cairo_show_text(cr_, text.c_str());
  cairo_restore(cr_);
}

void Canvas::image(const Image& img, Vec2 lo, Vec2 hi) {
  if (img.width <= 0 || img.height <= 0) return;
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, img.width, img.height);
  check(cairo_surface_status(s), "cairo image");
  cairo_surface_flush(s);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < img.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + y * stride);
    for (int x = 0; x < img.width; ++x) {
      const Colour& c = img.pixels[static_cast<std::size_t>(y * img.width + x)];
      // Premultiplied ARGB, as cairo keeps it.
      const auto byte = [](double v) {
        return static_cast<std::uint32_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
      };
      row[x] = byte(c.a) << 24 | byte(c.r * c.a) << 16 | byte(c.g * c.a) << 8 | byte(c.b * c.a);
    }
  }
  cairo_surface_mark_dirty(s);
  cairo_save(cr_);
  cairo_translate(cr_, lo.x, lo.y);
  cairo_scale(cr_, (hi.x - lo.x) / img.width, (hi.y - lo.y) / img.height);
  cairo_set_source_surface(cr_, s, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr_), CAIRO_FILTER_BILINEAR);
  cairo_pattern_set_extend(cairo_get_source(cr_), CAIRO_EXTEND_PAD);
  cairo_rectangle(cr_, 0, 0, img.width, img.height);
  cairo_fill(cr_);
  cairo_restore(cr_);
  cairo_surface_destroy(s);
}

void Canvas::push_clip(const std::vector<std::vector<Vec2>>& rings) {
  cairo_save(cr_);
  path(rings, true);
  cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_clip(cr_);
}

void Canvas::pop_clip() {
  cairo_restore(cr_);
}

std::string Canvas::finish() {
  if (raster_) throw std::logic_error("Canvas::finish on a raster canvas");
  cairo_destroy(cr_);
  cr_ = nullptr;
  if (format_ == FigureFormat::png) {
    check(cairo_surface_write_to_png_stream(surface_, append, bytes_.get()), "PNG");
  } else {
    cairo_surface_finish(surface_);
    check(cairo_surface_status(surface_), "cairo");
  }
  cairo_surface_destroy(surface_);
  surface_ = nullptr;
  return std::move(*bytes_);
}

const unsigned char* Canvas::pixels() {
  cairo_surface_flush(surface_);
  return cairo_image_surface_get_data(surface_);
}

int Canvas::stride() const {
  return cairo_image_surface_get_stride(surface_);
}

}  // namespace covsim
