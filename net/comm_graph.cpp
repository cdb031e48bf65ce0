#include "net/comm_graph.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <span>

#include "core/random_stream.hpp"
#include "net/channel.hpp"

namespace covsim {

namespace {

// Neighbour lists in one array (compressed rows); an edge appears in both endpoints' lists.
class Adjacency {
 public:
  Adjacency(std::size_t n, const CommEdges& edges) : start_(n + 1, 0), next_(2 * edges.size()) {
    for (auto [a, b] : edges) {
      ++start_[a + 1];
      ++start_[b + 1];
    }
    for (std::size_t v = 0; v < n; ++v)
      start_[v + 1] += start_[v];
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (auto [a, b] : edges) {
      next_[fill[a]++] = b;
      next_[fill[b]++] = a;
    }
  }
  std::size_t size() const { return start_.size() - 1; }
  std::span<const std::uint32_t> of(std::uint32_t v) const {
    return {next_.data() + start_[v], next_.data() + start_[v + 1]};
  }
  std::size_t degree(std::uint32_t v) const { return start_[v + 1] - start_[v]; }

 private:
  std::vector<std::uint32_t> start_, next_;
};

// Breadth-first searches that reset only what the previous search reached, so that a
// search costs the size of its component, not of the graph.
class Search {
 public:
  static constexpr std::uint32_t unreached = UINT32_MAX;
  explicit Search(const Adjacency& g) : g_(g), hops_(g.size(), unreached), parent_(g.size()) {}

  // Searches from s; returns s's eccentricity in its component. The nodes reached are
  // order() by hops, so the farthest is order().back().
  std::uint32_t from(std::uint32_t s) {
    for (std::uint32_t v : order_)
      hops_[v] = unreached;
    order_.clear();
    hops_[s] = 0;
    parent_[s] = s;
    order_.push_back(s);
    for (std::size_t head = 0; head < order_.size(); ++head) {
      const std::uint32_t v = order_[head];
      for (std::uint32_t w : g_.of(v)) {
        if (hops_[w] != unreached) continue;
        hops_[w] = hops_[v] + 1;
        parent_[w] = v;
        order_.push_back(w);
      }
    }
    return hops_[order_.back()];
  }
  const std::vector<std::uint32_t>& order() const { return order_; }
  std::uint32_t hops(std::uint32_t v) const { return hops_[v]; }
  // The node `back` steps from v towards the last search's source.
  std::uint32_t ancestor(std::uint32_t v, std::uint32_t back) const {
    for (; back > 0; --back)
      v = parent_[v];
    return v;
  }

 private:
  const Adjacency& g_;
  std::vector<std::uint32_t> hops_, parent_, order_;
};

// The diameter of the component whose nodes are `members`, exactly.
// A 4-sweep (Crescenzi et al. 2013) gives a lower bound and a central node u; iFUB then
// takes the eccentricities of the nodes farthest from u, level by level: once every pair
// left has both ends within i - 1 hops of u it is at most 2(i - 1) apart, so the search
// stops when the largest eccentricity found exceeds that. Usually a few searches; every
// node's at worst.
std::size_t component_diameter(Search& search, const Adjacency& g,
                               const std::vector<std::uint32_t>& members) {
  std::uint32_t hub = members.front();
  for (std::uint32_t v : members)
    if (g.degree(v) > g.degree(hub)) hub = v;
  std::uint32_t lower = 0;
  auto sweep_centre = [&](std::uint32_t start) {
    search.from(start);
    const std::uint32_t a = search.order().back();
    const std::uint32_t ecc = search.from(a);
    lower = std::max(lower, ecc);
    return search.ancestor(search.order().back(), ecc / 2);
  };
  const std::uint32_t u = sweep_centre(sweep_centre(hub));

  const std::uint32_t ecc_u = search.from(u);
  lower = std::max(lower, ecc_u);
  const std::vector<std::uint32_t> by_hops = search.order();
  std::vector<std::size_t> level_start(ecc_u + 2, by_hops.size());
  for (std::size_t k = by_hops.size(); k-- > 0;)
    level_start[search.hops(by_hops[k])] = k;

  std::uint32_t upper = 2 * ecc_u;
  for (std::uint32_t i = ecc_u; upper > lower; --i) {
    std::uint32_t level_max = 0;
    for (std::size_t k = level_start[i]; k < level_start[i + 1] && lower < upper; ++k) {
      level_max = std::max(level_max, search.from(by_hops[k]));
      lower = std::max(lower, level_max);
    }
    if (lower > 2 * (i - 1) || lower == upper) break;
    upper = 2 * (i - 1);
  }
  return lower;
}

// λ2 of the Laplacian L of a connected graph, as 1 / the largest eigenvalue of L⁺ on the
// vectors orthogonal to the constant one. L⁺x comes from the grounded Laplacian (L without
// one node's row and column, positive definite for a connected graph), factorised once:
// solve with x less that node's entry, put 0 there and subtract the mean. Lanczos with full
// reorthogonalisation from a fixed pseudo-random start; the top of L⁺'s spectrum (1/λ2,
// 1/λ3, ...) stands apart, so a few tens of steps usually suffice.
double sparse_algebraic_connectivity(const Adjacency& g, const CommEdges& edges) {
  // Bounds the basis (steps × n doubles); only a top of the spectrum clustered within about
  // 1e-4 relative needs as many, and then the estimate lies within the cluster.
  constexpr std::size_t lanczos_step_limit = 300;
  const std::size_t n = g.size();
  const auto m = static_cast<Eigen::Index>(n - 1);
  std::uint32_t ground = 0;
  for (std::uint32_t v = 0; v < n; ++v)
    if (g.degree(v) > g.degree(ground)) ground = v;
  auto reduced = [ground](std::uint32_t v) { return static_cast<Eigen::Index>(v - (v > ground)); };

  std::vector<Eigen::Triplet<double>> entries;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (v == ground) continue;
    entries.emplace_back(reduced(v), reduced(v), static_cast<double>(g.degree(v)));
    for (std::uint32_t w : g.of(v))
      if (w != ground && w < v) entries.emplace_back(reduced(v), reduced(w), -1.0);
  }
  Eigen::SparseMatrix<double> grounded(m, m);
  grounded.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> factor(grounded);
  // Positive definite in exact arithmetic; should rounding say otherwise, the dense way.
  if (factor.info() != Eigen::Success) return dense_algebraic_connectivity(n, edges);

  Eigen::VectorXd rhs(m);
  auto apply_pseudo_inverse = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    for (std::uint32_t v = 0; v < n; ++v)
      if (v != ground) rhs(reduced(v)) = x(v);
    const Eigen::VectorXd z = factor.solve(rhs);
    for (std::uint32_t v = 0; v < n; ++v)
      y(v) = v == ground ? 0.0 : z(reduced(v));
    y.array() -= y.mean();
  };

  RandomStream rng(0, n, "algebraic-connectivity-start");
  Eigen::VectorXd q(static_cast<Eigen::Index>(n));
  for (Eigen::Index v = 0; v < q.size(); ++v)
    q(v) = rng.uniform(-1.0, 1.0);
  q.array() -= q.mean();
  q.normalize();

  std::vector<Eigen::VectorXd> basis;
  std::vector<double> alpha, beta;
  Eigen::VectorXd w(q.size());
  double top = 0.0;
  const std::size_t steps = std::min(n - 1, lanczos_step_limit);
  for (std::size_t step = 0; step < steps; ++step) {
    basis.push_back(q);
    apply_pseudo_inverse(q, w);
    alpha.push_back(q.dot(w));
    // Full reorthogonalisation (twice is enough) against the basis and the constant vector.
    for (int pass = 0; pass < 2; ++pass) {
      for (const Eigen::VectorXd& b : basis)
        w -= b.dot(w) * b;
      w.array() -= w.mean();
    }
    const double next = w.norm();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz;
    const auto k = static_cast<Eigen::Index>(alpha.size());
    ritz.computeFromTridiagonal(Eigen::Map<const Eigen::VectorXd>(alpha.data(), k),
                                Eigen::Map<const Eigen::VectorXd>(beta.data(), k - 1),
                                Eigen::ComputeEigenvectors);
    top = ritz.eigenvalues()(k - 1);
    const double residual = next * std::abs(ritz.eigenvectors()(k - 1, k - 1));
    // A tiny `next` means the basis spans an invariant subspace: the Ritz values are exact.
    if (residual <= algebraic_connectivity_tolerance * top || next <= 1e-14 * top) break;
    beta.push_back(next);
    q = w / next;
  }
  return top > 0.0 ? 1.0 / top : 0.0;
}

}  // namespace

double dense_algebraic_connectivity(std::size_t n, const CommEdges& edges) {
  Eigen::MatrixXd laplacian =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (auto [a, b] : edges) {
    laplacian(a, b) -= 1.0;
    laplacian(b, a) -= 1.0;
    laplacian(a, a) += 1.0;
    laplacian(b, b) += 1.0;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(laplacian, Eigen::EigenvaluesOnly);
  // Eigenvalues come sorted ascending; the smallest is 0 (up to rounding).
  return std::max(0.0, solver.eigenvalues()(1));
}

CommGraphMetrics comm_graph_metrics(std::size_t n, const CommEdges& edges, bool spectrum) {
  CommGraphMetrics m;
  if (n == 0) return m;
  const Adjacency g(n, edges);
  m.average_degree = 2.0 * static_cast<double>(edges.size()) / static_cast<double>(n);

  Search search(g);
  std::vector<bool> seen(n, false);
  std::vector<std::uint32_t> members;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (seen[s]) continue;
    search.from(s);
    members = search.order();
    for (std::uint32_t v : members)
      seen[v] = true;
    ++m.components;
    m.largest_component = std::max(m.largest_component, members.size());
    // A component of k nodes is at most k - 1 across.
    if (members.size() - 1 > m.diameter)
      m.diameter = std::max(m.diameter, component_diameter(search, g, members));
  }

  if (n >= 2 && m.components == 1 && !spectrum) {
    m.algebraic_connectivity = std::numeric_limits<double>::quiet_NaN();
  } else if (n >= 2 && m.components == 1) {
    m.algebraic_connectivity = n <= dense_spectrum_limit ? dense_algebraic_connectivity(n, edges)
                                                         : sparse_algebraic_connectivity(g, edges);
  }
  return m;
}

CommGraphMetrics complete_graph_metrics(std::size_t n) {
  CommGraphMetrics m;
  if (n == 0) return m;
  m.components = 1;
  m.largest_component = n;
  m.diameter = n >= 2 ? 1 : 0;
  m.average_degree = static_cast<double>(n - 1);
  m.algebraic_connectivity = n >= 2 ? static_cast<double>(n) : 0.0;
  return m;
}

namespace {

CommEdges all_pairs(std::size_t n) {
  CommEdges pairs;
  pairs.reserve(n * (n - 1) / 2);
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      pairs.emplace_back(a, b);
  return pairs;
}

}  // namespace

CommEdges pairs_within(const std::vector<Vec2>& points, double radius) {
  CommEdges pairs;
  const std::size_t n = points.size();
  if (n < 2 || !(radius >= 0.0)) return pairs;
  const double keep = radius * radius * (1.0 + 1e-9);
  auto close = [&](std::uint32_t a, std::uint32_t b) {
    return norm2(points[a] - points[b]) <= keep;
  };
  Vec2 lo = points[0], hi = points[0];
  for (Vec2 p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  if (!std::isfinite(keep) || !is_finite(lo) || !is_finite(hi)) {
    for (auto [a, b] : all_pairs(n))
      if (close(a, b)) pairs.emplace_back(a, b);
    return pairs;
  }
  // Cells a little wider than the radius, so that rounding in the cell index never splits a
  // close pair by more than one cell; at most about n cells, so sparse points cost no more.
  const auto cap = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  double width = std::max(radius * (1.0 + 1e-6),
                          std::max(hi.x - lo.x, hi.y - lo.y) / static_cast<double>(cap));
  if (!(width > 0.0)) width = 1.0;  // every point in one place
  auto cells_over = [&](double extent) {
    return std::min(cap, static_cast<std::size_t>(extent / width)) + 1;
  };
  const std::size_t nx = cells_over(hi.x - lo.x), ny = cells_over(hi.y - lo.y);
  auto cell_of = [&](Vec2 p) {
    const auto cx = std::min(nx - 1, static_cast<std::size_t>((p.x - lo.x) / width));
    const auto cy = std::min(ny - 1, static_cast<std::size_t>((p.y - lo.y) / width));
    return cy * nx + cx;
  };
  // Points by cell.
  std::vector<std::uint32_t> start(nx * ny + 1, 0), by_cell(n);
  for (Vec2 p : points)
    ++start[cell_of(p) + 1];
  for (std::size_t c = 0; c < nx * ny; ++c)
    start[c + 1] += start[c];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t i = 0; i < n; ++i)
    by_cell[fill[cell_of(points[i])]++] = i;

  // Each point's partners of higher index from the 3 × 3 cells around it: the pairs come out
  // grouped by their first point, and only each group needs sorting.
  for (std::uint32_t a = 0; a < n; ++a) {
    const std::size_t c = cell_of(points[a]), cx = c % nx, cy = c / nx;
    const std::size_t group = pairs.size();
    for (std::size_t oy = cy > 0 ? cy - 1 : 0; oy <= std::min(cy + 1, ny - 1); ++oy) {
      for (std::size_t ox = cx > 0 ? cx - 1 : 0; ox <= std::min(cx + 1, nx - 1); ++ox) {
        const std::size_t o = oy * nx + ox;
        for (std::uint32_t k = start[o]; k < start[o + 1]; ++k) {
          const std::uint32_t b = by_cell[k];
          if (b > a && close(a, b)) pairs.emplace_back(a, b);
        }
      }
    }
    std::sort(pairs.begin() + static_cast<std::ptrdiff_t>(group), pairs.end());
  }
  return pairs;
}

CommEdges communication_edges(const Channel& channel, const std::vector<Vec2>& positions) {
  const std::optional<double>& range = channel.config().range;
  // An unlimited (or non-finite) range puts every pair in range: testing each is inherent.
  const CommEdges candidates = range && std::isfinite(*range) ? pairs_within(positions, *range)
                                                              : all_pairs(positions.size());
  CommEdges edges;
  for (auto [a, b] : candidates)
    if (channel.in_reach(positions[a], positions[b])) edges.emplace_back(a, b);
  return edges;
}

}  // namespace covsim
