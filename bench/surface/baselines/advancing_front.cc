#include "bench/surface/baselines/advancing_front.h"

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "bench/surface/baselines/baseline_input.h"
#include "core/surface/mesh_topology.h"

namespace avc::surface::baselines {
namespace {

constexpr const char* kAdvancingFront = "advancing front baseline";
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// CGAL's priority functor: the default (smallest Delaunay sphere radius) for facets within the
// perimeter bound, infinity (never taken) for the others. CGAL breaks ties between equal
// priorities by memory address, so each priority is nudged (1e-9 relative) by a hash of its
// facet's vertex ids: the same points then give the same surface.
struct PerimeterBound {
  double max_perimeter;

  template <typename AdvancingFront, typename CellHandle>
  double operator()(const AdvancingFront& front, CellHandle& cell, const int& index) const {
    double perimeter = 0.0;
    std::array<std::size_t, 3> ids{};
    for (int k = 1; k <= 3; ++k) {
      const auto& a = cell->vertex((index + k) & 3);
      const auto& b = cell->vertex((index + k % 3 + 1) & 3);
      perimeter += std::sqrt(CGAL::to_double(CGAL::squared_distance(a->point(), b->point())));
      ids[k - 1] = a->id();
    }
    if (perimeter > max_perimeter) return front.infinity();
    const double radius = front.smallest_radius_delaunay_sphere(cell, index);
    if (radius == front.infinity()) return radius;
    std::sort(ids.begin(), ids.end());
    uint64_t hash = 1469598103934665603ull;  // FNV-1a over the sorted ids
    for (std::size_t id : ids) hash = (hash ^ static_cast<uint64_t>(id)) * 1099511628211ull;
    return radius * (1.0 + 1e-9 * static_cast<double>(hash >> 11) * 0x1.0p-53);
  }
};

// The face's corners in ascending order: the same for both orientations.
Eigen::Vector3i SortedCorners(Eigen::Vector3i face) {
  std::sort(face.data(), face.data() + 3);
  return face;
}

bool LexicographicLess(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

// CGAL hands the facets out in an order, and each piece of surface in an orientation, that
// follow its memory layout. Each connected piece is turned so that its face with the smallest
// corners runs upwards in vertex index, faces are rotated to start at their smallest corner and
// sorted: the same points give the same bytes.
void CanonicalOrder(geometry::Mesh& mesh) {
  int count = 0;
  const std::vector<int> component = FaceComponents(mesh, &count);
  std::vector<int> reference(count, -1);  // per piece: its face with the smallest corners
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    int& r = reference[component[f]];
    if (r < 0 || LexicographicLess(SortedCorners(mesh.faces[f]), SortedCorners(mesh.faces[r]))) {
      r = static_cast<int>(f);
    }
  }
  const auto rotate_to_smallest = [](Eigen::Vector3i& face) {
    while (face[0] > face[1] || face[0] > face[2])
      face = Eigen::Vector3i(face[1], face[2], face[0]);
  };
  std::vector<bool> flip(count, false);
  for (int c = 0; c < count; ++c) {
    Eigen::Vector3i face = mesh.faces[reference[c]];
    rotate_to_smallest(face);
    flip[c] = face[1] > face[2];
  }
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    Eigen::Vector3i& face = mesh.faces[f];
    if (flip[component[f]]) std::swap(face[1], face[2]);
    rotate_to_smallest(face);
  }
  std::sort(mesh.faces.begin(), mesh.faces.end(), LexicographicLess);
}

}  // namespace

geometry::Mesh AdvancingFront(const geometry::PointCloud& cloud,
                              const AdvancingFrontOptions& options) {
  CheckBaselineInput(cloud, kAdvancingFront, /*require_normals=*/false);
  if (!(options.max_perimeter_factor > 0.0) || !(options.radius_ratio_bound > 0.0) ||
      !(options.beta > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "{}: max_perimeter_factor, radius_ratio_bound and beta must be > 0", kAdvancingFront));
  }
  const double spacing = ResolveSpacing(cloud, options.spacing, kAdvancingFront);
  std::vector<Kernel::Point_3> points;
  points.reserve(cloud.size());
  for (const Eigen::Vector3f& p : cloud.positions) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::advancing_front_surface_reconstruction(
      points.begin(), points.end(), std::back_inserter(facets),
      PerimeterBound{options.max_perimeter_factor * spacing}, options.radius_ratio_bound,
      options.beta);
  geometry::Mesh mesh;
  mesh.vertices = cloud.positions;
  mesh.faces.reserve(facets.size());
  for (const auto& f : facets) {
    mesh.faces.emplace_back(static_cast<int>(f[0]), static_cast<int>(f[1]), static_cast<int>(f[2]));
  }
  CanonicalOrder(mesh);
  RemoveUnusedVertices(mesh);
  return mesh;
}

}  // namespace avc::surface::baselines
