#include "core/traits/convex_hull_volume.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <Eigen/Geometry>
#include <cmath>

namespace avc::traits {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using HullMesh = CGAL::Surface_mesh<Point>;

Eigen::Vector3d ToEigen(const Point& p) { return {p.x(), p.y(), p.z()}; }

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
  // Divergence theorem over the (triangular, outward) hull faces.
  double volume = 0.0;
  for (const HullMesh::Face_index face : hull.faces()) {
    std::vector<Eigen::Vector3d> corners;
    for (const HullMesh::Vertex_index v : hull.vertices_around_face(hull.halfedge(face))) {
      corners.push_back(ToEigen(hull.point(v)));
    }
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      volume += corners[0].dot(corners[k].cross(corners[k + 1])) / 6.0;
    }
  }
  return std::abs(volume);
}

}  // namespace avc::traits
