#pragma once

// Groups of a point subset linked by chains of proximal neighbours: distinct groups at the
// point-spacing scale (the separation constraint's ground truth of "a gap"). Proximal means on
// the same local surface: closer than the link radius, and the offset between the two points lies
// near both tangent planes (|d.n| <= slope * |d| + allowance for each point's normal n), so two
// leaves stacked a few millimetres apart are not linked although they are within the radius;
// with a mean slope, also near the plane normal to the bisector of the two normals.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/cluster/point_grid.h"

namespace avc::cluster {

// The bisector slope the clusterer and the surfacer's pieces use (LinkRule::mean_slope): on the
// simulated plants it separates the rosette's stacked leaf bases (points of a cluster outside
// its majority leaf 1332 -> 355 of 3000) and leaves wavy margins joined (BENCHMARKS.md,
// clustering).
inline constexpr float kSameSurfaceMeanSlope = 0.1f;

struct LinkRule {
  float radius = 0;                                       // m
  const std::vector<Eigen::Vector3f>* normals = nullptr;  // unit; nullptr: distance only
  float slope = 0.5f;                                     // sin of the largest offset elevation
  float allowance = 0;                                    // m, noise allowance
  // When >= 0, the offset must also lie within mean_slope * |d| + allowance of the plane
  // normal to n_i + n_j. On any smooth bend the chord between two points is perpendicular to
  // the bisector of their normals (exactly on a circular arc), so this is strict for stacked
  // sheets (parallel normals, offset along them) and lenient for curved or wavy ones.
  float mean_slope = -1.0f;

  bool Linked(const std::vector<Eigen::Vector3f>& points, uint32_t i, uint32_t j) const {
    if (!normals) return true;
    const Eigen::Vector3f d = points[j] - points[i];
    const float limit = slope * d.norm() + allowance;
    if (std::abs(d.dot((*normals)[i])) > limit || std::abs(d.dot((*normals)[j])) > limit) {
      return false;
    }
    if (mean_slope < 0.0f) return true;
    const Eigen::Vector3f bisector = (*normals)[i] + (*normals)[j];
    const float length = bisector.norm();
    // Opposed normals have no bisector: the per-point test above has to do.
    return length < 1e-3f ||
           std::abs(d.dot(bisector)) <= (mean_slope * d.norm() + allowance) * length;
  }
};

// Components of subset under a neighbour relation: for_each_neighbour(i, visit) calls visit(j)
// for every neighbour j of point i. Each component is sorted ascending and they are ordered by
// their smallest index (deterministic). scratch must hold one int per point and all -1; it is
// restored before returning.
template <class ForEachNeighbour>
std::vector<std::vector<uint32_t>> ComponentsBy(const std::vector<uint32_t>& subset,
                                                std::vector<int32_t>* scratch,
                                                const ForEachNeighbour& for_each_neighbour) {
  constexpr int32_t kMember = 0;   // in the subset, not reached yet
  constexpr int32_t kReached = 1;  // in the subset, already in a component
  std::vector<int32_t>& mark = *scratch;
  for (uint32_t i : subset) mark[i] = kMember;
  std::vector<uint32_t> sorted = subset;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::vector<uint32_t>> components;
  std::vector<uint32_t> frontier;
  for (uint32_t seed : sorted) {
    if (mark[seed] != kMember) continue;
    std::vector<uint32_t> component{seed};
    mark[seed] = kReached;
    frontier.assign(1, seed);
    while (!frontier.empty()) {
      const uint32_t i = frontier.back();
      frontier.pop_back();
      for_each_neighbour(i, [&](uint32_t j) {
        if (mark[j] != kMember) return;
        mark[j] = kReached;
        component.push_back(j);
        frontier.push_back(j);
      });
    }
    std::sort(component.begin(), component.end());
    components.push_back(std::move(component));
  }
  for (uint32_t i : subset) mark[i] = -1;
  return components;
}

// Components of subset (indices into grid's points) linked by `link`, as ComponentsBy.
std::vector<std::vector<uint32_t>> ConnectedComponents(const PointGrid& grid,
                                                       const std::vector<Eigen::Vector3f>& points,
                                                       const std::vector<uint32_t>& subset,
                                                       const LinkRule& link,
                                                       std::vector<int32_t>* scratch);

}  // namespace avc::cluster
