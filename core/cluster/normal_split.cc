#include "core/cluster/normal_split.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace avc::cluster {
namespace {

// Dominant direction of a normal tensor and its eigenvalue (how many normals agree with it).
struct Dominant {
  double coherence = 0;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

Dominant DominantNormal(const Eigen::Matrix3d& tensor) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(tensor);
  return {solver.eigenvalues()[2], solver.eigenvectors().col(2)};
}

Eigen::Matrix3d Tensor(const std::vector<Eigen::Vector3f>& normals,
                       const std::vector<uint32_t>& indices) {
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  for (uint32_t i : indices) {
    const Eigen::Vector3d n = normals[i].cast<double>();
    tensor.noalias() += n * n.transpose();
  }
  return tensor;
}

}  // namespace

NormalSplit SplitByNormals(const std::vector<Eigen::Vector3f>& points,
                           const std::vector<Eigen::Vector3f>& normals,
                           const std::vector<uint32_t>& cluster, const PrincipalAxes& axes,
                           int axis_index, double bin_width, double min_gain,
                           int refinement_rounds) {
  NormalSplit split;
  if (cluster.size() < 2 || !(bin_width > 0.0)) return split;
  const Eigen::Vector3d axis = axes.axes.col(axis_index);
  std::vector<double> position(cluster.size());
  double lo = 0;
  double hi = 0;
  for (size_t k = 0; k < cluster.size(); ++k) {
    position[k] = (points[cluster[k]].cast<double>() - axes.centroid).dot(axis);
    lo = k == 0 ? position[k] : std::min(lo, position[k]);
    hi = k == 0 ? position[k] : std::max(hi, position[k]);
  }
  const size_t bins = static_cast<size_t>(std::floor((hi - lo) / bin_width)) + 1;
  if (bins < 2) return split;
  auto bin_of = [&](double p) {
    return std::min(bins - 1, static_cast<size_t>(std::floor((p - lo) / bin_width)));
  };
  std::vector<Eigen::Matrix3d> bin_tensor(bins, Eigen::Matrix3d::Zero());
  std::vector<size_t> bin_count(bins, 0);
  for (size_t k = 0; k < cluster.size(); ++k) {
    const size_t b = bin_of(position[k]);
    const Eigen::Vector3d n = normals[cluster[k]].cast<double>();
    bin_tensor[b].noalias() += n * n.transpose();
    ++bin_count[b];
  }
  Eigen::Matrix3d total = Eigen::Matrix3d::Zero();
  for (const Eigen::Matrix3d& t : bin_tensor) total += t;
  const double whole = DominantNormal(total).coherence;

  // Cut after bin c (left = bins 0..c): maximise C(L) + C(R), i.e. minimise A + B.
  Eigen::Matrix3d left = Eigen::Matrix3d::Zero();
  double best = -1.0;
  size_t best_cut = 0;
  for (size_t c = 0; c + 1 < bins; ++c) {
    left += bin_tensor[c];
    if (bin_count[c] == 0) continue;  // same sides as the previous cut
    const double coherence =
        DominantNormal(left).coherence + DominantNormal(total - left).coherence;
    if (coherence > best + 1e-12) {
      best = coherence;
      best_cut = c;
    }
  }
  if (best < 0.0) return split;
  // The cut itself must pay off: refining a useless cut (a tube cut across) would otherwise
  // peel the tube into lengthwise strips of aligned normals.
  split.gain = (best - whole) / static_cast<double>(cluster.size());
  if (split.gain < min_gain) return split;
  std::vector<uint8_t> side(cluster.size());
  for (size_t k = 0; k < cluster.size(); ++k) side[k] = bin_of(position[k]) <= best_cut ? 0 : 1;

  auto collect = [&](uint8_t s) {
    std::vector<uint32_t> out;
    for (size_t k = 0; k < cluster.size(); ++k) {
      if (side[k] == s) out.push_back(cluster[k]);
    }
    return out;
  };
  for (int round = 0; round < refinement_rounds; ++round) {
    const Dominant a = DominantNormal(Tensor(normals, collect(0)));
    const Dominant b = DominantNormal(Tensor(normals, collect(1)));
    std::vector<uint8_t> next = side;
    size_t moved = 0;
    size_t left_count = 0;
    for (size_t k = 0; k < cluster.size(); ++k) {
      const Eigen::Vector3d n = normals[cluster[k]].cast<double>();
      const double fit_a = std::abs(n.dot(a.direction));
      const double fit_b = std::abs(n.dot(b.direction));
      // A clear preference only: points fitting both about equally keep their side.
      if (fit_a > fit_b + 0.05) next[k] = 0;
      if (fit_b > fit_a + 0.05) next[k] = 1;
      moved += next[k] != side[k];
      left_count += next[k] == 0;
    }
    if (left_count == 0 || left_count == cluster.size()) break;
    side = next;
    if (moved == 0) break;
  }
  split.left = collect(0);
  split.right = collect(1);
  split.gain = (DominantNormal(Tensor(normals, split.left)).coherence +
                DominantNormal(Tensor(normals, split.right)).coherence - whole) /
               static_cast<double>(cluster.size());
  return split;
}

}  // namespace avc::cluster
