#include "core/eval/triangle_tree.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace avc::eval {
namespace {

// Exact predicates keep line-of-sight tests right for segments ending just off a surface.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point ToPoint(const Eigen::Vector3d& p) { return Point(p.x(), p.y(), p.z()); }

}  // namespace

struct TriangleTree::Impl {
  std::vector<Triangle> triangles;
  std::vector<int32_t> face_of_triangle;  // mesh face index of each kept triangle
  Tree tree;
};

TriangleTree::TriangleTree(const geometry::Mesh& mesh, const std::string& what)
    : impl_(std::make_unique<Impl>()) {
  if (const std::string problem = mesh.Validate(); !problem.empty()) {
    throw std::invalid_argument(fmt::format("{}: {}", what, problem));
  }
  impl_->triangles.reserve(mesh.num_faces());
  impl_->face_of_triangle.reserve(mesh.num_faces());
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3i& face = mesh.faces[f];
    const Triangle triangle(ToPoint(mesh.vertices[face[0]].cast<double>()),
                            ToPoint(mesh.vertices[face[1]].cast<double>()),
                            ToPoint(mesh.vertices[face[2]].cast<double>()));
    if (triangle.is_degenerate()) continue;
    impl_->triangles.push_back(triangle);
    impl_->face_of_triangle.push_back(static_cast<int32_t>(f));
  }
  if (impl_->triangles.empty()) {
    throw std::invalid_argument(fmt::format("{}: no surface (of {} faces none has a non-zero area)",
                                            what, mesh.num_faces()));
  }
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  // Build both trees now: concurrent const queries then never trigger a lazy build.
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();
}

TriangleTree::~TriangleTree() = default;

TriangleTree::Nearest TriangleTree::Closest(const Eigen::Vector3d& query) const {
  const Point q = ToPoint(query);
  const auto [closest, primitive] = impl_->tree.closest_point_and_primitive(q);
  Nearest nearest;
  nearest.distance = std::sqrt(CGAL::to_double(CGAL::squared_distance(q, closest)));
  nearest.face =
      impl_->face_of_triangle[static_cast<size_t>(primitive - impl_->triangles.cbegin())];
  return nearest;
}

bool TriangleTree::SegmentHits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  return impl_->tree.do_intersect(Kernel::Segment_3(ToPoint(a), ToPoint(b)));
}

}  // namespace avc::eval
