#pragma once
// Exact moments of an isotropic Gaussian over a convex polygon, by Green's theorem: a cost of
// edges, not of area (docs/architecture.md, "Gaussian moments").
//
// In units of sigma about the mean, with φ the standard normal density, the first and second
// moments reduce to closed forms along the edges (∫ zφ = -∮ φ n ds, ∫ |z|²φ = 2∫φ - ∮ (z·n)φ ds,
// the line integrals by erf), and the mass to one integral per edge of a smooth function:
// the fan triangle from the mean to the edge (near the mean), or the edge's shadow, the part
// of the wedge it subtends that lies beyond it (far from the mean, where the mass must keep
// its relative precision however small it is). Both are taken by Gauss-Legendre on pieces
// short against the integrand's scale, the shadow's far tail by Gauss-Laguerre. Polygons
// whose extent times distance is tiny are integrated directly on their fan of triangles.
// Relative error against an independent long double reference: below 1e-13 for polygons
// not thinner than 1e-3 sigma, 1e-11 for slivers 1e-4 sigma thin ten sigma away
// (tests/geometry/test_gaussian_moments.cpp).
#include "geometry/convex_polygon.hpp"

namespace covsim {

// Moments of g(x) = exp(-|x - mean|² / (2 sigma²)) over a convex polygon (counter-clockwise)
// about r: mass ∫g, first ∫(x - r)g, second ∫|x - r|²g. Fewer than three vertices: zero.
Moments gaussian_moments(const ConvexPolygon& polygon, Vec2 mean, double sigma, Vec2 r);

}  // namespace covsim
