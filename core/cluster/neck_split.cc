#include "core/cluster/neck_split.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <utility>

#include "core/cluster/fiedler_vector.h"
#include "core/cluster/pca.h"

namespace avc::cluster {
namespace {

using Edge = std::pair<uint32_t, uint32_t>;  // local vertex ids, first < second

// Symmetrised k-nearest-neighbour edges over the cluster (each point's k nearest same-surface
// neighbours that are in the cluster).
// reach receives each vertex's distance to the furthest of its k neighbours (m).
std::vector<Edge> NeighbourEdges(const NeighbourLists& neighbours,
                                 const std::vector<Eigen::Vector3f>& points,
                                 const std::vector<uint32_t>& cluster, int k,
                                 std::vector<int32_t>* scratch, std::vector<float>* reach) {
  std::vector<int32_t>& local = *scratch;
  for (size_t v = 0; v < cluster.size(); ++v) local[cluster[v]] = static_cast<int32_t>(v);
  std::vector<Edge> edges;
  edges.reserve(cluster.size() * static_cast<size_t>(k));
  for (size_t v = 0; v < cluster.size(); ++v) {
    const uint32_t self = static_cast<uint32_t>(v);
    int taken = 0;
    for (const uint32_t* j = neighbours.begin(cluster[v]);
         j != neighbours.end(cluster[v]) && taken < k; ++j) {
      if (local[*j] < 0) continue;
      const uint32_t u = static_cast<uint32_t>(local[*j]);
      edges.emplace_back(std::min(self, u), std::max(self, u));
      (*reach)[v] = (points[*j] - points[cluster[v]]).norm();
      ++taken;
    }
  }
  for (uint32_t i : cluster) local[i] = -1;
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// Normal continuity: an edge whose end normals bend much more than is typical here is weak. The
// floor keeps every vertex's degree positive.
std::vector<float> EdgeWeights(const std::vector<Edge>& edges, const std::vector<uint32_t>& cluster,
                               const std::vector<Eigen::Vector3f>* unit_normals,
                               double bend_factor) {
  std::vector<float> weight(edges.size(), 1.0f);
  if (!unit_normals || !(bend_factor > 0.0) || edges.empty()) return weight;
  const std::vector<Eigen::Vector3f>& normals = *unit_normals;
  std::vector<float> bend(edges.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    const float cosine = normals[cluster[edges[e].first]].dot(normals[cluster[edges[e].second]]);
    bend[e] = 1.0f - std::abs(cosine);
  }
  std::vector<float> sorted = bend;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double typical = *middle;
  if (!(typical > 0.0)) return weight;
  for (size_t e = 0; e < edges.size(); ++e) {
    weight[e] = std::max(1e-3f, static_cast<float>(std::exp(-bend[e] / (bend_factor * typical))));
  }
  return weight;
}

SparseGraph ToGraph(size_t vertices, const std::vector<Edge>& edges,
                    const std::vector<float>& weight) {
  SparseGraph graph;
  graph.offset.assign(vertices + 1, 0);
  for (const auto& [a, b] : edges) {
    ++graph.offset[a + 1];
    ++graph.offset[b + 1];
  }
  std::partial_sum(graph.offset.begin(), graph.offset.end(), graph.offset.begin());
  graph.column.resize(graph.offset.back());
  graph.weight.resize(graph.offset.back());
  std::vector<uint32_t> fill(graph.offset.begin(), graph.offset.end() - 1);
  for (size_t e = 0; e < edges.size(); ++e) {
    const auto [a, b] = edges[e];
    graph.weight[fill[a]] = weight[e];
    graph.column[fill[a]++] = b;
    graph.weight[fill[b]] = weight[e];
    graph.column[fill[b]++] = a;
  }
  return graph;
}

struct SweepCut {
  size_t size = 0;  // vertices on side A (the first in Fiedler order); 0: none allowed
  double cut = 0;
};

// Least-conductance prefix of the order with both sides at least min_side vertices.
SweepCut LeastConductanceCut(const SparseGraph& graph, const std::vector<uint32_t>& order,
                             size_t min_side, double total_volume) {
  const size_t n = order.size();
  std::vector<uint8_t> in_a(n, 0);
  double cut = 0.0;
  double volume_a = 0.0;
  double best_conductance = 2.0;
  SweepCut best;
  for (size_t s = 0; s + 1 < n; ++s) {
    const uint32_t v = order[s];
    double to_a = 0.0;
    double degree = 0.0;
    for (uint32_t e = graph.offset[v]; e < graph.offset[v + 1]; ++e) {
      degree += graph.weight[e];
      if (in_a[graph.column[e]]) to_a += graph.weight[e];
    }
    in_a[v] = 1;
    cut += degree - 2.0 * to_a;  // v's edges to A stop being cut, its edges to B start
    volume_a += degree;
    const size_t size_a = s + 1;
    if (size_a < min_side || n - size_a < min_side) continue;
    const double conductance = cut / std::min(volume_a, total_volume - volume_a);
    if (conductance < best_conductance) {
      best_conductance = conductance;
      best = {size_a, cut};
    }
  }
  return best;
}

}  // namespace

NeckCut SplitAtNeck(const NeighbourLists& neighbours, const std::vector<Eigen::Vector3f>& points,
                    const std::vector<Eigen::Vector3f>* normals,
                    const std::vector<uint32_t>& cluster, const NeckRule& rule,
                    std::vector<int32_t>* scratch) {
  NeckCut result;
  result.ratio = std::numeric_limits<double>::infinity();
  const size_t n = cluster.size();
  if (n < 2 * std::max<size_t>(rule.min_side, 2)) return result;
  std::vector<float> reach(n, 0.0f);
  const std::vector<Edge> edges =
      NeighbourEdges(neighbours, points, cluster, rule.neighbours, scratch, &reach);
  const SparseGraph graph =
      ToGraph(n, edges, EdgeWeights(edges, cluster, normals, rule.bend_factor));
  // A vertex without a same-surface neighbour leaves the spectrum degenerate; such clusters are
  // the connected-component split's business, not a neck's.
  for (size_t v = 0; v < n; ++v) {
    if (graph.offset[v + 1] == graph.offset[v]) return result;
  }
  // The longest axis is the Fiedler vector's first guess for an elongated pair of leaves.
  const PrincipalAxes axes = FitPrincipalAxes(points, cluster);
  std::vector<double> start(n);
  for (size_t v = 0; v < n; ++v) {
    start[v] = (points[cluster[v]].cast<double>() - axes.centroid).dot(axes.LongestAxis());
  }
  const std::vector<double> fiedler = FiedlerVector(graph, start, rule.lanczos_steps);
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return fiedler[a] < fiedler[b]; });

  double total_volume = 0.0;
  for (float w : graph.weight) total_volume += w;
  const SweepCut best = LeastConductanceCut(graph, order, rule.min_side, total_volume);
  if (best.size == 0) return result;
  result.groups.resize(2);
  for (size_t s = 0; s < n; ++s) result.groups[s < best.size ? 0 : 1].push_back(cluster[order[s]]);
  for (auto& group : result.groups) std::sort(group.begin(), group.end());
  // On a sheet sampled with density rho, a straight cut of length l crosses (2/3) rho^2 l r^3
  // edges of reach r, and a vertex has pi rho r^2: l = (3 pi / 2) (cut / degree) / (rho r) with
  // rho r^2 = k / pi, so l = (3 pi^2 / 2k) (cut / degree) r.
  const auto middle = reach.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(reach.begin(), middle, reach.end());
  const double mean_degree = total_volume / static_cast<double>(n);
  const double neck_length = 1.5 * std::numbers::pi * std::numbers::pi /
                             static_cast<double>(rule.neighbours) * (best.cut / mean_degree) *
                             static_cast<double>(*middle);
  // A side's width: 2 sqrt(3 lambda_mid) (exact for a rectangle's shorter side).
  double narrower = std::numeric_limits<double>::infinity();
  for (const auto& group : result.groups) {
    const PrincipalAxes side = FitPrincipalAxes(points, group);
    narrower = std::min(narrower, 2.0 * std::sqrt(3.0 * std::max(0.0, side.eigenvalues[1])));
  }
  result.ratio = narrower > 0.0 ? neck_length / narrower : std::numeric_limits<double>::infinity();
  if (!(result.ratio <= rule.max_neck_ratio)) result.groups.clear();
  return result;
}

}  // namespace avc::cluster
