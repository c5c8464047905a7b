#include "core/surface/delaunay_2d.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstdint>
#include <utility>

namespace avc::surface {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;

}  // namespace

std::vector<Eigen::Vector3i> Delaunay2d(const std::vector<Eigen::Vector2d>& points) {
  std::vector<Eigen::Vector3i> triangles;
  if (points.size() < 3) return triangles;
  std::vector<std::pair<Kernel::Point_2, int>> input;
  input.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    input.emplace_back(Kernel::Point_2(points[i].x(), points[i].y()), static_cast<int>(i));
  }
  // The range insertion's spatial sort shuffles with a fixed-seed generator: deterministic.
  const Delaunay delaunay(input.begin(), input.end());
  if (delaunay.dimension() < 2) return triangles;
  triangles.reserve(delaunay.number_of_faces());
  for (auto face = delaunay.finite_faces_begin(); face != delaunay.finite_faces_end(); ++face) {
    triangles.emplace_back(face->vertex(0)->info(), face->vertex(1)->info(),
                           face->vertex(2)->info());
  }
  // Canonical order (each triangle rotated to start at its smallest index, then sorted), so the
  // output does not depend on CGAL's internal storage order.
  for (Eigen::Vector3i& t : triangles) {
    while (t[0] > t[1] || t[0] > t[2]) t = Eigen::Vector3i(t[1], t[2], t[0]);
  }
  std::sort(triangles.begin(), triangles.end(),
            [](const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
              return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
            });
  return triangles;
}

}  // namespace avc::surface
