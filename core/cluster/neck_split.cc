#include "core/cluster/neck_split.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "core/cluster/pca.h"
#include "core/util/upper_median.h"

namespace avc::cluster {
namespace {

// The kept cut's sides redrawn on the graph weighted by elevation too (neck_split.h).
std::vector<uint8_t> RedrawnBoundary(const ClusterGraph& graph,
                                     const std::vector<Eigen::Vector3f>& points,
                                     const std::vector<Eigen::Vector3f>& local_normals,
                                     const std::vector<uint32_t>& cluster,
                                     const std::vector<float>& bend_weights, const SpectralCut& cut,
                                     const NeckRule& rule) {
  const size_t n = cluster.size();
  std::vector<uint8_t> side = CutSideOfVertex(cut);
  std::vector<float> weights = BendWeights(
      EdgeElevations(graph.edges, points, cluster, local_normals), rule.elevation_factor);
  for (size_t e = 0; e < weights.size(); ++e) {
    weights[e] = std::max(1e-3f, weights[e] * bend_weights[e]);
  }
  const SparseGraph weighted = WeightedGraph(n, graph.edges, weights);
  // The first cut's Fiedler order starts the Krylov space: the redrawn vector lies close to it, so
  // half the steps do (20, 30 and 40 give the same Table 2 scores).
  std::vector<double> start(n);
  for (size_t s = 0; s < n; ++s) start[cut.order[s]] = static_cast<double>(s);
  const SpectralCut again =
      LeastConductanceCut(weighted, start, std::max(2, rule.lanczos_steps / 2), rule.min_side);
  if (again.size > 0) {
    std::vector<uint8_t> redrawn = CutSideOfVertex(again);
    size_t changed = 0;
    for (size_t v = 0; v < n; ++v) changed += redrawn[v] != side[v];
    if (2 * changed > n) {  // the same two sides, named the other way round
      for (uint8_t& s : redrawn) s = 1 - s;
      changed = n - changed;
    }
    const size_t smaller = std::min(cut.size, n - cut.size);
    if (static_cast<double>(changed) <= rule.max_boundary_shift * static_cast<double>(smaller)) {
      side = std::move(redrawn);
    }
  }
  std::vector<uint8_t> refined = side;
  RefineCut(weighted, rule.refinement_rounds, &refined);
  const size_t side_a = static_cast<size_t>(std::count(refined.begin(), refined.end(), 0));
  if (side_a < rule.min_side || n - side_a < rule.min_side) return side;
  return refined;
}

}  // namespace

NeckCut SplitAtNeck(const ClusterGraph& graph, const std::vector<Eigen::Vector3f>& points,
                    const std::vector<Eigen::Vector3f>* normals,
                    const std::vector<uint32_t>& cluster, const NeckRule& rule) {
  NeckCut result;
  result.ratio = std::numeric_limits<double>::infinity();
  const size_t n = cluster.size();
  if (n < 2 * std::max<size_t>(rule.min_side, 2)) return result;
  std::vector<float> weights(graph.edges.size(), 1.0f);
  std::vector<Eigen::Vector3f> local_normals;
  if (normals) {
    local_normals.resize(n);
    for (size_t v = 0; v < n; ++v) local_normals[v] = (*normals)[cluster[v]];
  }
  if (normals && rule.bend_factor > 0.0) {
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
  if (!(result.ratio <= rule.max_neck_ratio)) {
    result.groups.clear();
  } else if (normals && rule.elevation_factor > 0.0) {
    result.groups = CutSides(
        cluster, RedrawnBoundary(graph, points, local_normals, cluster, weights, best, rule));
  }
  return result;
}

}  // namespace avc::cluster
