#include "core/cluster/neck_split.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/cluster/pca.h"

namespace avc::cluster {

NeckCut SplitAtNeck(const ClusterGraph& graph, const std::vector<Eigen::Vector3f>& points,
                    const std::vector<Eigen::Vector3f>* normals,
                    const std::vector<uint32_t>& cluster, const NeckRule& rule) {
  NeckCut result;
  result.ratio = std::numeric_limits<double>::infinity();
  const size_t n = cluster.size();
  if (n < 2 * std::max<size_t>(rule.min_side, 2)) return result;
  std::vector<float> weights(graph.edges.size(), 1.0f);
  if (normals && rule.bend_factor > 0.0) {
    std::vector<Eigen::Vector3f> local_normals(n);
    for (size_t v = 0; v < n; ++v) local_normals[v] = (*normals)[cluster[v]];
    weights = BendWeights(EdgeBends(graph.edges, local_normals), rule.bend_factor);
  }
  const SpectralCut best =
      LeastConductanceCut(WeightedGraph(n, graph.edges, weights), LongestAxisStart(points, cluster),
                          rule.lanczos_steps, rule.min_side);
  if (best.size == 0) return result;
  result.groups = CutSides(cluster, best);
  // On a sheet sampled with density rho, a straight cut of length l crosses (2/3) rho^2 l r^3
  // edges of reach r, and a vertex has pi rho r^2: l = (3 pi / 2) (cut / degree) / (rho r) with
  // rho r^2 = k / pi, so l = (3 pi^2 / 2k) (cut / degree) r.
  const double mean_degree = best.total_volume / static_cast<double>(n);
  const double neck_length = 1.5 * std::numbers::pi * std::numbers::pi /
                             static_cast<double>(rule.neighbours) * (best.cut / mean_degree) *
                             static_cast<double>(UpperMedian(graph.reach));
  // A side's width: 2 sqrt(3 lambda_mid) (exact for a rectangle's shorter side).
  double narrower = std::numeric_limits<double>::infinity();
  for (const auto& group : result.groups) {
    const PrincipalAxes axes = FitPrincipalAxes(points, group);
    narrower = std::min(narrower, 2.0 * std::sqrt(3.0 * std::max(0.0, axes.eigenvalues[1])));
  }
  result.ratio = narrower > 0.0 ? neck_length / narrower : std::numeric_limits<double>::infinity();
  if (!(result.ratio <= rule.max_neck_ratio)) result.groups.clear();
  return result;
}

}  // namespace avc::cluster
