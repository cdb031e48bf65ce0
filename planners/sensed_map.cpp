#include "planners/sensed_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/predicates.hpp"

namespace covsim {

namespace {
constexpr std::int32_t kMargin = 2;  // cells beyond the bounds
constexpr double kMaxCells = double(1 << 24);
}  // namespace

SensedMap::SensedMap(const Box& bounds, double resolution, double tolerance, double spread)
    : bounds_(bounds),
      h_(resolution),
      tol_(tolerance),
      spread_(spread),
      merge_(std::max(tolerance, 3.0 * spread)) {
  if (!(resolution > 0.0)) throw std::invalid_argument("a sensed map's cells need a side > 0");
  const Vec2 size = bounds.size();
  const double nx = std::ceil(size.x / h_) + 2 * kMargin, ny = std::ceil(size.y / h_) + 2 * kMargin;
  if (nx * ny > kMaxCells)
    throw std::invalid_argument("a sensed map of more than 16777216 cells: raise the resolution");
  nx_ = static_cast<std::int32_t>(nx);
  ny_ = static_cast<std::int32_t>(ny);
  origin_ = bounds.lo - Vec2{kMargin * h_, kMargin * h_};
  wall_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), 0);
  in_cell_.resize(wall_.size());
}

std::unique_ptr<SensedMap> SensedMap::finer(std::int32_t factor, double max_cells) const {
  const double h = h_ / factor;
  const Vec2 size = bounds_.size();
  if ((std::ceil(size.x / h) + 2 * kMargin) * (std::ceil(size.y / h) + 2 * kMargin) > max_cells)
    return nullptr;
  auto out = std::make_unique<SensedMap>(bounds_, h, tol_, spread_);
  for (const Piece& p : pieces_)
    out->add_stretches(p.a, p.b, out->merge_, p.exact);
  return out;
}

Vec2 SensedMap::center(std::uint32_t c) const {
  return origin_ + Vec2{(column(c) + 0.5) * h_, (row(c) + 0.5) * h_};
}

std::uint32_t SensedMap::cell_of(Vec2 p) const {
  const auto i =
      std::clamp(static_cast<std::int32_t>(std::floor((p.x - origin_.x) / h_)), 0, nx_ - 1);
  const auto j =
      std::clamp(static_cast<std::int32_t>(std::floor((p.y - origin_.y) / h_)), 0, ny_ - 1);
  return index(i, j);
}

std::vector<SensedMap::Gap> SensedMap::uncovered(Vec2 a, Vec2 b, double merge) const {
  // The pieces held along the same line, facing the same way, cover the union of their
  // stretches over a -> b; what they leave, by more than `merge`, is new.
  const Vec2 d = b - a;
  const double len = norm(d);
  if (len <= tol_) return {};
  const Vec2 e = d / len;
  struct Span {
    double lo, hi;
    std::uint32_t piece;
    bool operator<(const Span& o) const { return lo < o.lo || (lo == o.lo && piece < o.piece); }
  };
  std::vector<Span> spans;
  ++query_;
  for_each_cell(a, b, [&](std::int32_t i, std::int32_t j) {
    if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return true;
    for (const std::uint32_t k : in_cell_[index(i, j)]) {
      if (seen_[k] == query_) continue;
      seen_[k] = query_;
      const Piece& s = pieces_[k];
      const Vec2 sd = s.b - s.a;
      const double sl = norm(sd);
      if (sl <= 0.0 || dot(sd, d) <= 0.0) continue;
      if (std::fabs(cross(sd, a - s.a)) / sl > merge || std::fabs(cross(sd, b - s.a)) / sl > merge)
        continue;
      spans.push_back(Span{dot(s.a - a, e), dot(s.b - a, e), k});
    }
    return true;
  });
  std::sort(spans.begin(), spans.end());
  std::vector<Gap> gaps;
  double reach = 0.0, held = -INFINITY;  // held: the farthest end of a piece so far
  std::optional<std::uint32_t> by;       // the piece that ends there
  const auto ending = [&]() { return held >= -merge ? by : std::nullopt; };
  for (const Span& s : spans) {
    if (reach >= len - merge) break;
    if (s.lo > reach + merge)
      gaps.push_back(Gap{reach, std::min(s.lo, len), ending(),
                         s.lo <= len + merge ? std::optional(s.piece) : std::nullopt});
    if (s.hi > held) {
      held = s.hi;
      by = s.piece;
    }
    reach = std::max(reach, held);
  }
  if (reach < len - merge) gaps.push_back(Gap{reach, len, ending(), std::nullopt});
  return gaps;
}

bool SensedMap::add_wall(Vec2 a, Vec2 b) {
  return add_stretches(a, b, merge_, spread_ == 0.0);
}

bool SensedMap::add_stretches(Vec2 a, Vec2 b, double merge, bool exact) {
  if (!is_finite(a) || !is_finite(b)) return false;
  // Only the stretches not held yet, each joined to the piece it continues: a wall shown by
  // many readings stays a few pieces, however its stretches came into view.
  const auto gaps = uncovered(a, b, merge);
  const double len = distance(a, b);
  for (const Gap& g : gaps) {
    const Vec2 u = g.before        ? pieces_[*g.before].b
                   : g.from <= 0.0 ? a
                                   : a + (g.from / len) * (b - a);
    const Vec2 v = g.after ? pieces_[*g.after].a : g.to >= len ? b : a + (g.to / len) * (b - a);
    // A stretch extends a piece of its own kind only: a touched stretch joined to a noisy
    // piece would lose what the touch showed, or lend its exactness to a noisy one.
    std::uint32_t k = 0;
    if (g.before && pieces_[*g.before].exact == exact) {
      k = *g.before;
      pieces_[k].b = v;
    } else if (g.after && pieces_[*g.after].exact == exact) {
      k = *g.after;
      pieces_[k].a = u;
    } else {
      k = static_cast<std::uint32_t>(pieces_.size());
      pieces_.push_back(Piece{u, v, exact});
      seen_.push_back(0);
      cells_.emplace_back();
    }
    added_.push_back(Piece{u, v, exact});
    mark(u, v, k);
  }
  return !gaps.empty();
}

void SensedMap::mark(Vec2 a, Vec2 b, std::uint32_t k) {
  for_each_cell(a, b, [&](std::int32_t i, std::int32_t j) {
    if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return true;
    const std::uint32_t c = index(i, j);
    if (std::find(in_cell_[c].begin(), in_cell_[c].end(), k) == in_cell_[c].end()) {
      in_cell_[c].push_back(k);
      cells_[k].push_back(c);
    }
    if (wall_[c] == 0) {
      wall_[c] = 1;
      ++wall_cells_;
      ++version_;
    }
    return true;
  });
}

void SensedMap::remove(std::uint32_t k) {
  for (const std::uint32_t c : cells_[k]) {
    auto& in = in_cell_[c];
    in.erase(std::find(in.begin(), in.end(), k));
    if (in.empty()) {
      wall_[c] = 0;
      --wall_cells_;
      ++version_;
    }
  }
  const auto last = static_cast<std::uint32_t>(pieces_.size() - 1);
  if (k != last) {
    for (const std::uint32_t c : cells_[last])
      *std::find(in_cell_[c].begin(), in_cell_[c].end(), last) = k;
    pieces_[k] = pieces_[last];
    cells_[k] = std::move(cells_[last]);
  }
  pieces_.pop_back();
  cells_.pop_back();
  seen_.pop_back();
}

void SensedMap::supersede(Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len = norm(d);
  if (len <= tol_) return;
  const Vec2 e = d / len;
  // The noisy pieces in the cells within one of the stretch's (a piece within the noise of it
  // may lie in the next cell).
  std::vector<std::uint32_t> near;
  ++query_;
  for_each_cell(a, b, [&](std::int32_t i, std::int32_t j) {
    for (std::int32_t dj = -1; dj <= 1; ++dj)
      for (std::int32_t di = -1; di <= 1; ++di) {
        const std::int32_t ci = i + di, cj = j + dj;
        if (ci < 0 || cj < 0 || ci >= nx_ || cj >= ny_) continue;
        for (const std::uint32_t k : in_cell_[index(ci, cj)])
          if (seen_[k] != query_) {
            seen_[k] = query_;
            if (!pieces_[k].exact && dot(pieces_[k].b - pieces_[k].a, d) > 0.0) near.push_back(k);
          }
      }
    return true;
  });
  // Highest index first: removing a piece moves only the last one.
  std::sort(near.rbegin(), near.rend());
  std::vector<Piece> kept;
  bool removed = false;
  for (const std::uint32_t k : near) {
    const Piece s = pieces_[k];
    // Along s (t from 0 to 1): the distance off the stretch's line and the position along it
    // are linear in t; the part explained has both within bounds.
    double lo = 0.0, hi = 1.0;
    const auto within = [&](double v0, double v1, double from, double to) {
      // {t : from <= v0 + (v1 - v0) t <= to}, narrowing [lo, hi].
      const double dv = v1 - v0;
      if (dv == 0.0) {
        if (v0 < from || v0 > to) hi = -1.0;
        return;
      }
      double t0 = (from - v0) / dv, t1 = (to - v0) / dv;
      if (t0 > t1) std::swap(t0, t1);
      lo = std::max(lo, t0);
      hi = std::min(hi, t1);
    };
    within(cross(e, s.a - a), cross(e, s.b - a), -merge_, merge_);
    within(dot(e, s.a - a), dot(e, s.b - a), 0.0, len);
    const double sl = distance(s.a, s.b);
    if (!((hi - lo) * sl > tol_)) continue;
    removed = true;
    remove(k);
    if (lo * sl > tol_) kept.push_back(Piece{s.a, s.a + lo * (s.b - s.a), false});
    if ((1.0 - hi) * sl > tol_) kept.push_back(Piece{s.a + hi * (s.b - s.a), s.b, false});
  }
  if (removed) ++supersessions_;
  for (const Piece& p : kept) {
    const auto k = static_cast<std::uint32_t>(pieces_.size());
    pieces_.push_back(p);
    seen_.push_back(0);
    cells_.emplace_back();
    mark(p.a, p.b, k);
  }
}

bool SensedMap::add(const SensorReading& r) {
  bool added = false;
  for (const SensedPiece& p : r.visible().pieces)
    added = add_wall(p.a, p.b) || added;
  // A touch shows the wall where the robot stands, not the whole edge it lies on: a cell's
  // side either way of the point of contact.
  for (const ContactEdge& c : r.contacts) {
    const double len = distance(c.a, c.b);
    if (!(len > 0.0)) continue;
    const double at = project_to_segment(r.position, c.a, c.b).t * len;
    const double from = std::max(0.0, at - h_), to = std::min(len, at + h_);
    const Vec2 u = c.a + (from / len) * (c.b - c.a), v = c.a + (to / len) * (c.b - c.a);
    if (spread_ > 0.0) supersede(u, v);
    added = add_stretches(u, v, tol_, true) || added;
  }
  return added;
}

bool SensedMap::leaves_free(Vec2 p, Vec2 d) const {
  // Interior to a piece: its left. At a corner where one piece ends and another begins:
  // either's left at a convex corner of the obstacle, both at a concave one. At a lone end:
  // round it, any way.
  const auto left = [&](const Piece& s) { return cross(s.b - s.a, d) >= 0.0; };
  const Piece *in = nullptr, *out = nullptr;
  const double tol2 = tol_ * tol_;
  const std::uint32_t c = cell_of(p);
  const auto for_each_near = [&](auto&& f) {
    ++query_;
    for (std::int32_t dj = -1; dj <= 1; ++dj)
      for (std::int32_t di = -1; di <= 1; ++di) {
        const std::int32_t i = column(c) + di, j = row(c) + dj;
        if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
        for (const std::uint32_t k : in_cell_[index(i, j)])
          if (seen_[k] != query_) {
            seen_[k] = query_;
            f(pieces_[k]);
          }
      }
  };
  // Within the noise of a noisy piece's interior is on it (it may pass between the robot and
  // the free space it stands in), unless p touches a wall held exactly: that wall tells the
  // free side (at a thin wall's end the noisy pieces of both faces would leave no way out).
  bool touching = false;
  if (spread_ > 0.0)
    for_each_near([&](const Piece& s) {
      touching = touching || (s.exact && norm2(p - project_to_segment(p, s.a, s.b).point) <= tol2);
    });
  const auto near2 = [&](const Piece& s, const SegmentProjection& pr) {
    return !s.exact && !touching && pr.t > 0.0 && pr.t < 1.0 ? merge_ * merge_ : tol2;
  };
  bool ok = true;
  ++query_;
  for (std::int32_t dj = -1; dj <= 1 && ok; ++dj) {
    for (std::int32_t di = -1; di <= 1 && ok; ++di) {
      const std::int32_t i = column(c) + di, j = row(c) + dj;
      if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
      for (const std::uint32_t k : in_cell_[index(i, j)]) {
        if (seen_[k] == query_) continue;
        seen_[k] = query_;
        const Piece& s = pieces_[k];
        if (norm2(p - s.b) <= tol2) {
          in = &s;
        } else if (norm2(p - s.a) <= tol2) {
          out = &s;
        } else if (const SegmentProjection pr = project_to_segment(p, s.a, s.b);
                   norm2(p - pr.point) <= near2(s, pr) && !left(s)) {
          ok = false;
          break;
        }
      }
    }
  }
  if (!ok) return false;
  if (in == nullptr || out == nullptr) return true;
  if (orientation(in->a, in->b, out->b) < 0) return left(*in) || left(*out);
  return left(*in) && left(*out);
}

double SensedMap::cell_distance2(std::int32_t i, std::int32_t j, Vec2 p) const {
  const Vec2 lo = origin_ + Vec2{i * h_, j * h_};
  const double dx = std::max({lo.x - p.x, 0.0, p.x - (lo.x + h_)});
  const double dy = std::max({lo.y - p.y, 0.0, p.y - (lo.y + h_)});
  return dx * dx + dy * dy;
}

bool SensedMap::clear(Vec2 p, Vec2 q) const {
  if (distance(p, q) <= tol_) return true;
  // The wall cells first (a leg that meets one far from its ends is rejected without its
  // pieces), then the sides it leaves and reaches walls by, then the pieces it meets.
  const double near2 = 4.0 * h_ * h_;
  const auto far_wall = [&](std::int32_t i, std::int32_t j) {
    const bool inside = i >= 0 && j >= 0 && i < nx_ && j < ny_;
    return (!inside || wall_[index(i, j)] != 0) && cell_distance2(i, j, p) > near2 &&
           cell_distance2(i, j, q) > near2;
  };
  if (!for_each_cell(p, q, [&](std::int32_t i, std::int32_t j) { return !far_wall(i, j); }))
    return false;
  if (!leaves_free(p, q - p) || !leaves_free(q, p - q)) return false;
  const double tol2 = tol_ * tol_;
  std::vector<std::uint32_t> met;
  ++query_;
  for_each_cell(p, q, [&](std::int32_t i, std::int32_t j) {
    if (i >= 0 && j >= 0 && i < nx_ && j < ny_)
      for (const std::uint32_t k : in_cell_[index(i, j)])
        if (seen_[k] != query_) {
          seen_[k] = query_;
          met.push_back(k);
        }
    return true;
  });
  for (const std::uint32_t k : met) {
    const Piece& s = pieces_[k];
    // A piece an end lies on (to rounding, or within the noise of its interior) is for
    // leaves_free.
    const auto on = [&](Vec2 e) {
      const SegmentProjection pr = project_to_segment(e, s.a, s.b);
      return norm2(e - pr.point) <= (!s.exact && pr.t > 0.0 && pr.t < 1.0 ? merge_ * merge_ : tol2);
    };
    const int o1 = orientation(p, q, s.a), o2 = orientation(p, q, s.b);
    const int o3 = orientation(s.a, s.b, p), o4 = orientation(s.a, s.b, q);
    if (o1 * o2 < 0 && o3 * o4 < 0 && !on(p) && !on(q)) return false;  // crosses it
    // Through one of its ends (a corner, or where two readings' pieces meet): the leg must
    // pass on the free side there.
    for (const Vec2 w : {s.a, s.b}) {
      if (norm2(w - project_to_segment(w, p, q).point) > tol2 || norm2(w - p) <= tol2 ||
          norm2(w - q) <= tol2)
        continue;
      if (dot(w - p, q - p) <= 0.0 || dot(w - q, p - q) <= 0.0) continue;
      if (!leaves_free(w, p - w) || !leaves_free(w, q - w)) return false;
    }
  }
  return true;
}

std::optional<std::uint32_t> SensedMap::entry(Vec2 p, std::int32_t rings,
                                              const std::vector<std::uint8_t>* within) const {
  const std::uint32_t c = cell_of(p);
  const std::int32_t ci = column(c), cj = row(c);
  for (std::int32_t r = 0; r <= rings; ++r) {
    std::optional<std::uint32_t> best;
    double least = INFINITY;
    for (std::int32_t j = cj - r; j <= cj + r; ++j) {
      for (std::int32_t i = ci - r; i <= ci + r; ++i) {
        if (std::max(std::abs(i - ci), std::abs(j - cj)) != r || !free(i, j)) continue;
        const std::uint32_t k = index(i, j);
        if (within != nullptr && (*within)[k] == 0) continue;
        const double d = distance(p, center(k));
        if (d < least && clear(p, center(k))) {
          least = d;
          best = k;
        }
      }
    }
    if (best) return best;
  }
  return std::nullopt;
}

std::optional<SensedMap::Landing> SensedMap::closest_reachable_wall(
    Vec2 g, const std::vector<std::uint8_t>& reachable) const {
  std::optional<Landing> best;
  double least = INFINITY;
  for (const Piece& s : pieces_) {
    const Vec2 q = project_to_segment(g, s.a, s.b).point;
    const double d = distance(g, q);
    if (!(d < least)) continue;
    const std::uint32_t c = cell_of(q);
    std::optional<std::uint32_t> from;
    double nearest = INFINITY;
    for (std::int32_t j = row(c) - 2; j <= row(c) + 2; ++j) {
      for (std::int32_t i = column(c) - 2; i <= column(c) + 2; ++i) {
        if (!free(i, j) || reachable[index(i, j)] == 0) continue;
        const std::uint32_t k = index(i, j);
        const double dk = distance(q, center(k));
        if (dk < nearest && clear(center(k), q)) {
          nearest = dk;
          from = k;
        }
      }
    }
    if (from) {
      least = d;
      best = Landing{q, *from};
    }
  }
  return best;
}

}  // namespace covsim
