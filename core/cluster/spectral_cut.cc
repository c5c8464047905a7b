#include "core/cluster/spectral_cut.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/cluster/pca.h"
#include "core/util/upper_median.h"

namespace avc::cluster {
namespace {

// The sweep over the order: side A grows one vertex at a time.
void SweepOrder(const SparseGraph& graph, size_t min_side, SpectralCut* result) {
  const size_t n = result->order.size();
  std::vector<uint8_t> in_a(n, 0);
  double cut = 0.0;
  double volume_a = 0.0;
  double best_conductance = 2.0;
  for (size_t s = 0; s + 1 < n; ++s) {
    const uint32_t v = result->order[s];
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
    const double conductance = cut / std::min(volume_a, result->total_volume - volume_a);
    if (conductance < best_conductance) {
      best_conductance = conductance;
      result->size = size_a;
      result->cut = cut;
    }
  }
}

}  // namespace

ClusterGraph NeighbourGraph(const NeighbourLists& neighbours,
                            const std::vector<Eigen::Vector3f>& points,
                            const std::vector<uint32_t>& cluster, int k,
                            std::vector<int32_t>* scratch) {
  std::vector<int32_t>& local = *scratch;
  for (size_t v = 0; v < cluster.size(); ++v) local[cluster[v]] = static_cast<int32_t>(v);
  const size_t per_vertex = static_cast<size_t>(std::max(k, 0));
  // Each vertex's k nearest neighbours in the cluster (count[v] of them).
  std::vector<uint32_t> nearest(cluster.size() * per_vertex);
  std::vector<uint32_t> count(cluster.size(), 0);
  ClusterGraph graph;
  graph.reach.assign(cluster.size(), 0.0f);
  for (size_t v = 0; v < cluster.size(); ++v) {
    for (const uint32_t* j = neighbours.begin(cluster[v]);
         j != neighbours.end(cluster[v]) && count[v] < per_vertex; ++j) {
      if (local[*j] < 0) continue;
      nearest[v * per_vertex + count[v]++] = static_cast<uint32_t>(local[*j]);
      graph.reach[v] = (points[*j] - points[cluster[v]]).norm();
    }
  }
  for (uint32_t i : cluster) local[i] = -1;
  // Symmetrise: u -> v is kept unless v -> u was already kept from the smaller end.
  auto lists = [&](uint32_t u, uint32_t v) {
    const uint32_t* first = nearest.data() + u * per_vertex;
    return std::find(first, first + count[u], v) != first + count[u];
  };
  graph.edges.reserve(cluster.size() * per_vertex);
  for (uint32_t v = 0; v < cluster.size(); ++v) {
    for (uint32_t s = 0; s < count[v]; ++s) {
      const uint32_t u = nearest[v * per_vertex + s];
      if (u > v || !lists(u, v)) graph.edges.emplace_back(std::min(u, v), std::max(u, v));
    }
  }
  return graph;
}

std::vector<float> EdgeBends(const std::vector<LocalEdge>& edges,
                             const std::vector<Eigen::Vector3f>& local_normals) {
  std::vector<float> bends(edges.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    const float cosine = local_normals[edges[e].first].dot(local_normals[edges[e].second]);
    bends[e] = 1.0f - std::abs(cosine);
  }
  return bends;
}

std::vector<float> EdgeElevations(const std::vector<LocalEdge>& edges,
                                  const std::vector<Eigen::Vector3f>& points,
                                  const std::vector<uint32_t>& cluster,
                                  const std::vector<Eigen::Vector3f>& local_normals) {
  std::vector<float> elevations(edges.size(), 0.0f);
  for (size_t e = 0; e < edges.size(); ++e) {
    const auto [a, b] = edges[e];
    const Eigen::Vector3f d = points[cluster[b]] - points[cluster[a]];
    const float squared_length = d.squaredNorm();
    if (!(squared_length > 0.0f)) continue;
    const float rise =
        std::max(std::abs(d.dot(local_normals[a])), std::abs(d.dot(local_normals[b])));
    elevations[e] = rise * rise / squared_length;
  }
  return elevations;
}

std::vector<float> BendWeights(const std::vector<float>& bends, double bend_factor) {
  std::vector<float> weights(bends.size(), 1.0f);
  if (!(bend_factor > 0.0) || bends.empty()) return weights;
  const double typical = UpperMedian(bends);
  if (!(typical > 0.0)) return weights;
  for (size_t e = 0; e < bends.size(); ++e) {
    weights[e] = std::max(1e-3f, static_cast<float>(std::exp(-bends[e] / (bend_factor * typical))));
  }
  return weights;
}

SparseGraph WeightedGraph(size_t vertices, const std::vector<LocalEdge>& edges,
                          const std::vector<float>& weights) {
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
    graph.weight[fill[a]] = weights[e];
    graph.column[fill[a]++] = b;
    graph.weight[fill[b]] = weights[e];
    graph.column[fill[b]++] = a;
  }
  return graph;
}

SpectralCut LeastConductanceCut(const SparseGraph& graph, const std::vector<double>& start,
                                int lanczos_steps, size_t min_side) {
  SpectralCut result;
  const size_t vertices = graph.Vertices();
  for (size_t v = 0; v < vertices; ++v) {
    if (graph.offset[v + 1] == graph.offset[v]) return result;
  }
  const std::vector<double> fiedler = FiedlerVector(graph, start, lanczos_steps);
  result.order.resize(vertices);
  std::iota(result.order.begin(), result.order.end(), 0u);
  std::stable_sort(result.order.begin(), result.order.end(),
                   [&](uint32_t a, uint32_t b) { return fiedler[a] < fiedler[b]; });
  for (float w : graph.weight) result.total_volume += w;
  SweepOrder(graph, min_side, &result);
  return result;
}

std::vector<uint8_t> CutSideOfVertex(const SpectralCut& cut) {
  std::vector<uint8_t> side(cut.order.size(), 1);
  for (size_t s = 0; s < cut.size; ++s) side[cut.order[s]] = 0;
  return side;
}

void RefineCut(const SparseGraph& graph, int rounds, std::vector<uint8_t>* side) {
  std::vector<uint8_t>& of = *side;
  for (int round = 0; round < rounds; ++round) {
    size_t moved = 0;
    for (size_t v = 0; v < graph.Vertices(); ++v) {
      double to[2] = {0.0, 0.0};
      for (uint32_t e = graph.offset[v]; e < graph.offset[v + 1]; ++e) {
        to[of[graph.column[e]]] += graph.weight[e];
      }
      const uint8_t other = 1 - of[v];
      if (to[other] > to[of[v]]) {
        of[v] = other;
        ++moved;
      }
    }
    if (moved == 0) break;
  }
}

double CutWeight(const SparseGraph& graph, const std::vector<uint8_t>& side) {
  double cut = 0.0;
  for (size_t v = 0; v < graph.Vertices(); ++v) {
    for (uint32_t e = graph.offset[v]; e < graph.offset[v + 1]; ++e) {
      if (side[graph.column[e]] != side[v]) cut += graph.weight[e];
    }
  }
  return 0.5 * cut;  // every edge is stored at both ends
}

std::vector<std::vector<uint32_t>> CutSides(const std::vector<uint32_t>& cluster,
                                            const std::vector<uint8_t>& side) {
  std::vector<std::vector<uint32_t>> sides(2);
  for (size_t v = 0; v < cluster.size(); ++v) sides[side[v]].push_back(cluster[v]);
  for (auto& group : sides) std::sort(group.begin(), group.end());
  return sides;
}

std::vector<std::vector<uint32_t>> CutSides(const std::vector<uint32_t>& cluster,
                                            const SpectralCut& cut) {
  return CutSides(cluster, CutSideOfVertex(cut));
}

std::vector<double> LongestAxisStart(const std::vector<Eigen::Vector3f>& points,
                                     const std::vector<uint32_t>& cluster) {
  const PrincipalAxes axes = FitPrincipalAxes(points, cluster);
  std::vector<double> start(cluster.size());
  for (size_t v = 0; v < cluster.size(); ++v) {
    start[v] = (points[cluster[v]].cast<double>() - axes.centroid).dot(axes.LongestAxis());
  }
  return start;
}

}  // namespace avc::cluster
