#pragma once

// Groups of a point subset linked by chains of proximal neighbours: distinct groups at the
// point-spacing scale (the separation constraint's ground truth of "a gap"). Proximal means on
// the same local surface: closer than the link radius, and the offset between the two points lies
// near both tangent planes (|d.n| <= slope * |d| + allowance for each point's normal n), so two
// leaves stacked a few millimetres apart are not linked although they are within the radius.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/cluster/point_grid.h"

namespace avc::cluster {

struct LinkRule {
  float radius = 0;                                       // m
  const std::vector<Eigen::Vector3f>* normals = nullptr;  // unit; nullptr: distance only
  float slope = 0.5f;                                     // sin of the largest offset elevation
  float allowance = 0;                                    // m, noise allowance

  bool Linked(const std::vector<Eigen::Vector3f>& points, uint32_t i, uint32_t j) const {
    if (!normals) return true;
    const Eigen::Vector3f d = points[j] - points[i];
    const float limit = slope * d.norm() + allowance;
    return std::abs(d.dot((*normals)[i])) <= limit && std::abs(d.dot((*normals)[j])) <= limit;
  }
};

// Components of subset (indices into grid's points), each sorted ascending, ordered by their
// smallest index (deterministic). scratch must hold one int per point and all -1; it is
// restored before returning.
std::vector<std::vector<uint32_t>> ConnectedComponents(const PointGrid& grid,
                                                       const std::vector<Eigen::Vector3f>& points,
                                                       const std::vector<uint32_t>& subset,
                                                       const LinkRule& link,
                                                       std::vector<int32_t>* scratch);

}  // namespace avc::cluster
