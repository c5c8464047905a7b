#pragma once

// The input and output of clustering (paper §3, Algorithm 2): a merged plant point cloud with
// normals, optionally with ground-truth labels (benchmarks and tests), and a cluster id per point.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace avc::cluster {

// Cluster id of an outlier or unassigned point (in an Assignment and in ground-truth labels).
inline constexpr int32_t kUnassigned = -1;

struct PointSet {
  std::string name;
  std::vector<Eigen::Vector3f> points;   // metres
  std::vector<Eigen::Vector3f> normals;  // unit, one per point
  // Ground truth, one per point (organ: leaf i, stem, ...; kUnassigned for injected outliers);
  // empty when unknown.
  std::vector<int32_t> labels;
};

// A cluster id per point (0..K-1), kUnassigned for points a method leaves out.
using Assignment = std::vector<int32_t>;

}  // namespace avc::cluster
