#include "geometry/reversals.hpp"

#include <algorithm>
#include <limits>
#include <optional>

namespace covsim {

namespace {

// How far back from path[to] along the polyline path[from..to] the point nearest p lies (arc
// length), if p lies within `tolerance` of it.
std::optional<double> back_along(const std::vector<Vec2>& path, std::size_t from, std::size_t to,
                                 Vec2 p, double tolerance) {
  double best = std::numeric_limits<double>::infinity(), arc = 0.0, at = 0.0;
  for (std::size_t k = to; k > from; --k) {
    const SegmentProjection q = project_to_segment(p, path[k], path[k - 1]);
    const double d = distance(q.point, p);
    if (d < best) {
      best = d;
      at = arc + distance(path[k], q.point);
    }
    arc += distance(path[k], path[k - 1]);
  }
  if (best > tolerance) return std::nullopt;
  return at;
}

}  // namespace

std::vector<std::size_t> reversals(const std::vector<Vec2>& path, double min_length,
                                   double tolerance) {
  std::vector<std::size_t> out;
  const std::size_t n = path.size();
  std::size_t k = 1;
  while (k + 1 < n) {
    // A turn at k: the way in (from the last position apart from it) against the way out.
    std::size_t in = k, out_of = k;
    while (in > 0 && !beyond(path[in - 1], path[k], tolerance))
      --in;
    while (out_of + 1 < n && !beyond(path[out_of + 1], path[k], tolerance))
      ++out_of;
    if (in == 0 || out_of + 1 >= n ||
        dot(path[k] - path[in - 1], path[out_of + 1] - path[k]) >= 0.0) {
      k = out_of + 1;
      continue;
    }
    // The way it came, back to min_length (and a tolerance) before the turn.
    std::size_t back = k;
    double came = 0.0;
    while (back > 0 && came < min_length + tolerance) {
      came += distance(path[back - 1], path[back]);
      --back;
    }
    // How far back over that ground the way on goes, while it stays on it, within min_length
    // of the turn along the way on.
    double reached = 0.0, gone = 0.0;
    std::size_t on = k;
    while (came >= min_length && gone < min_length && on + 1 < n) {
      const double step = distance(path[on], path[on + 1]);
      const Vec2 p = gone + step <= min_length
                         ? path[on + 1]
                         : path[on] + ((min_length - gone) / step) * (path[on + 1] - path[on]);
      const std::optional<double> at = back_along(path, back, k, p, tolerance);
      if (!at) break;
      reached = std::max(reached, *at);
      gone += step;
      ++on;
    }
    if (reached >= min_length - tolerance) {
      out.push_back(out_of);  // where the way back begins
      k = on;                 // one reversal per turn
    } else {
      k = out_of + 1;
    }
  }
  return out;
}

}  // namespace covsim
