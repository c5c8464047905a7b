#include "core/traits/convex_hull_volume.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>

namespace avc::traits {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using HullMesh = CGAL::Surface_mesh<Point>;

// p0 . (p1 x p2), exactly: six times the signed volume of the tetrahedron (origin, p0, p1, p2).
CGAL::Exact_rational TripleProduct(const Point& p0, const Point& p1, const Point& p2) {
  using Exact = CGAL::Exact_rational;
  const Exact x0(p0.x()), y0(p0.y()), z0(p0.z());
  const Exact x1(p1.x()), y1(p1.y()), z1(p1.z());
  const Exact x2(p2.x()), y2(p2.y()), z2(p2.z());
  return x0 * (y1 * z2 - z1 * y2) - y0 * (x1 * z2 - z1 * x2) + z0 * (x1 * y2 - y1 * x2);
}

}  // namespace

double ConvexHullVolume(const std::vector<Eigen::Vector3f>& points) {
  if (points.size() < 4) return 0.0;
  std::vector<Point> input;
  input.reserve(points.size());
  for (const Eigen::Vector3f& p : points) input.emplace_back(p.x(), p.y(), p.z());
  // Coplanar input: no volume (and CGAL would return a polygon, not a closed hull).
  size_t a = 0, b = 0, c = 0;
  for (size_t i = 1; i < input.size() && b == 0; ++i) {
    if (input[i] != input[a]) b = i;
  }
  for (size_t i = 1; i < input.size() && c == 0 && b != 0; ++i) {
    if (!CGAL::collinear(input[a], input[b], input[i])) c = i;
  }
  if (b == 0 || c == 0) return 0.0;
  bool has_volume = false;
  for (const Point& p : input) {
    if (!CGAL::coplanar(input[a], input[b], input[c], p)) {
      has_volume = true;
      break;
    }
  }
  if (!has_volume) return 0.0;

  HullMesh hull;
  CGAL::convex_hull_3(input.begin(), input.end(), hull);
  // Divergence theorem over the (outward) hull faces, summed exactly: CGAL lists the faces, and
  // triangulates coplanar ones, in an order that depends on the process's memory layout, and a
  // floating-point sum would change in its last digits with it (traits.csv differed between two
  // runs of the same demo). The exact sum is the polytope's volume whatever the order.
  CGAL::Exact_rational six_volume = 0;
  for (const HullMesh::Face_index face : hull.faces()) {
    std::vector<Point> corners;
    for (const HullMesh::Vertex_index v : hull.vertices_around_face(hull.halfedge(face))) {
      corners.push_back(hull.point(v));
    }
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      six_volume += TripleProduct(corners[0], corners[k], corners[k + 1]);
    }
  }
  return std::abs(CGAL::to_double(six_volume) / 6.0);
}

}  // namespace avc::traits
