#include "bench/clustering/baselines/ipddp.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/clustering/baselines/input_checks.h"
#include "bench/clustering/baselines/relabel.h"

namespace avc::cluster::baselines {
namespace {

struct Leaf {
  std::vector<int32_t> indices;
  double gap = 0;  // largest gap in the band; 0 when the leaf may not be split
  std::vector<int32_t> left, right;
};

// Fills gap/left/right with the leaf's best split, or leaves gap = 0 when none is allowed.
void PlanSplit(const PointSet& set, const IpddpOptions& options, Leaf& leaf) {
  const size_t n = leaf.indices.size();
  if (n <= static_cast<size_t>(options.min_sample_split)) return;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int32_t i : leaf.indices) mean += set.points[static_cast<size_t>(i)].cast<double>();
  mean /= static_cast<double>(n);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (int32_t i : leaf.indices) {
    const Eigen::Vector3d d = set.points[static_cast<size_t>(i)].cast<double>() - mean;
    scatter += d * d.transpose();
  }
  const Eigen::Vector3d axis =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(
          2);  // eigenvalues ascend: PC1 is the last
  std::vector<double> projection(n);
  for (size_t j = 0; j < n; ++j) {
    projection[j] =
        axis.dot(set.points[static_cast<size_t>(leaf.indices[j])].cast<double>() - mean);
  }
  std::vector<double> sorted = projection;
  std::sort(sorted.begin(), sorted.end());
  const double last = static_cast<double>(n - 1);
  const size_t low = static_cast<size_t>(std::floor(options.percentile * last));
  const size_t high = static_cast<size_t>(std::ceil((1.0 - options.percentile) * last));
  double best_gap = 0, split = 0;
  for (size_t j = low; j < high; ++j) {
    const double gap = sorted[j + 1] - sorted[j];
    if (gap > best_gap) best_gap = gap, split = sorted[j] + 0.5 * gap;
  }
  if (best_gap <= 0) return;
  leaf.gap = best_gap;
  for (size_t j = 0; j < n; ++j) {
    (projection[j] <= split ? leaf.left : leaf.right).push_back(leaf.indices[j]);
  }
}

}  // namespace

Assignment IpddpClustering(const PointSet& set, const IpddpOptions& options) {
  CheckPoints(set, "iPDDP");
  if (options.max_clusters < 1) throw std::invalid_argument("iPDDP: max_clusters must be >= 1");
  if (!(options.percentile >= 0 && options.percentile < 0.5)) {
    throw std::invalid_argument("iPDDP: percentile must be in [0, 0.5)");
  }
  if (options.min_sample_split < 1) {
    throw std::invalid_argument("iPDDP: min_sample_split must be >= 1");
  }
  std::vector<Leaf> leaves(1);
  leaves[0].indices.resize(set.points.size());
  for (size_t i = 0; i < set.points.size(); ++i) leaves[0].indices[i] = static_cast<int32_t>(i);
  PlanSplit(set, options, leaves[0]);
  while (static_cast<int>(leaves.size()) < options.max_clusters) {
    size_t pick = leaves.size();
    for (size_t l = 0; l < leaves.size(); ++l) {
      if (leaves[l].gap > 0 && (pick == leaves.size() || leaves[l].gap > leaves[pick].gap))
        pick = l;
    }
    if (pick == leaves.size()) break;  // no leaf may be split
    Leaf right;
    right.indices = std::move(leaves[pick].right);
    Leaf left;
    left.indices = std::move(leaves[pick].left);
    PlanSplit(set, options, left);
    PlanSplit(set, options, right);
    leaves[pick] = std::move(left);
    leaves.push_back(std::move(right));
  }
  Assignment assignment(set.points.size(), kUnassigned);
  for (size_t l = 0; l < leaves.size(); ++l) {
    for (int32_t i : leaves[l].indices)
      assignment[static_cast<size_t>(i)] = static_cast<int32_t>(l);
  }
  return RelabelByFirstAppearance(assignment);
}

}  // namespace avc::cluster::baselines
