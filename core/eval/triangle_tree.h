#pragma once

// Point-to-surface distances and line-of-sight tests against a triangle mesh, via a CGAL AABB
// tree. Built once; every query is const and safe to run from many threads at once.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>

#include "core/geometry/mesh.h"

namespace avc::eval {

class TriangleTree {
 public:
  struct Nearest {
    double distance = 0;  // metres, to the closest point of the surface
    int32_t face = -1;    // index of the mesh face holding that point
  };

  // Degenerate (zero-area) faces are left out: they add no surface. Throws
  // std::invalid_argument naming `what` when the mesh is inconsistent or has no area.
  TriangleTree(const geometry::Mesh& mesh, const std::string& what);
  ~TriangleTree();
  TriangleTree(const TriangleTree&) = delete;
  TriangleTree& operator=(const TriangleTree&) = delete;

  Nearest Closest(const Eigen::Vector3d& query) const;
  // True when the closed segment a-b touches any triangle (exact predicates).
  bool SegmentHits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace avc::eval
