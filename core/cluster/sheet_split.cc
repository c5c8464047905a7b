#include "core/cluster/sheet_split.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/util/upper_median.h"

namespace avc::cluster {
namespace {

// Each vertex's normal plus its neighbours' (sign-aligned) along edges bent at most `limit`.
std::vector<Eigen::Vector3f> SmoothedNormals(const std::vector<LocalEdge>& edges,
                                             const std::vector<float>& bends,
                                             const std::vector<Eigen::Vector3f>& local_normals,
                                             float limit) {
  std::vector<Eigen::Vector3f> smoothed = local_normals;
  for (size_t e = 0; e < edges.size(); ++e) {
    if (bends[e] > limit) continue;
    const auto [a, b] = edges[e];
    const float sign = local_normals[a].dot(local_normals[b]) >= 0.0f ? 1.0f : -1.0f;
    smoothed[a] += sign * local_normals[b];
    smoothed[b] += sign * local_normals[a];
  }
  for (Eigen::Vector3f& normal : smoothed) normal.normalize();
  return smoothed;
}

// The Fiedler vector's first guess for two sheets: each normal's component along the second
// principal direction of the normal tensor (the two sheets' normals differ along it), signed by
// the first (normal signs do not matter), plus a trace of the longest axis so it is never
// constant.
std::vector<double> NormalSpreadStart(const std::vector<Eigen::Vector3f>& points,
                                      const std::vector<uint32_t>& cluster,
                                      const std::vector<Eigen::Vector3f>& local_normals) {
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3f& normal : local_normals) {
    const Eigen::Vector3d n = normal.cast<double>();
    tensor.noalias() += n * n.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(tensor);
  const Eigen::Vector3d dominant = solver.eigenvectors().col(2);
  const Eigen::Vector3d spread = solver.eigenvectors().col(1);
  std::vector<double> start = LongestAxisStart(points, cluster);
  double extent = 0.0;
  for (double s : start) extent = std::max(extent, std::abs(s));
  for (size_t v = 0; v < start.size(); ++v) {
    const Eigen::Vector3d n = local_normals[v].cast<double>();
    const double sign = n.dot(dominant) >= 0.0 ? 1.0 : -1.0;
    start[v] = sign * n.dot(spread) + (extent > 0.0 ? 1e-3 * start[v] / extent : 0.0);
  }
  return start;
}

// The larger of the two sides' edge biases: for every vertex at the cut (an end of a cut edge),
// the mean offset of its own-side neighbours in its tangent plane, projected on the direction of
// its other-side neighbours, over their mean distance, negated: 2/pi right at the straight edge of
// a sheet that ends at the cut, 0 (plus sampling noise) for one that surrounds the point.
double EdgeBias(const NeighbourLists& neighbours, const std::vector<Eigen::Vector3f>& points,
                const std::vector<uint32_t>& cluster, const std::vector<LocalEdge>& edges,
                const std::vector<uint8_t>& side,
                const std::vector<Eigen::Vector3f>& tangent_normals, size_t min_boundary,
                std::vector<int32_t>* scratch) {
  const size_t n = cluster.size();
  std::vector<uint8_t> at_cut(n, 0);
  for (const auto& [a, b] : edges) {
    if (side[a] != side[b]) at_cut[a] = at_cut[b] = 1;
  }
  std::vector<int32_t>& local = *scratch;
  for (size_t v = 0; v < n; ++v) local[cluster[v]] = static_cast<int32_t>(v);
  std::vector<float> bias[2];
  for (size_t v = 0; v < n; ++v) {
    if (!at_cut[v]) continue;
    const Eigen::Vector3f& p = points[cluster[v]];
    const Eigen::Vector3f& normal = tangent_normals[v];
    Eigen::Vector3f own = Eigen::Vector3f::Zero();
    Eigen::Vector3f other = Eigen::Vector3f::Zero();
    float own_distance = 0.0f;
    int own_count = 0;
    for (const uint32_t* j = neighbours.begin(cluster[v]); j != neighbours.end(cluster[v]); ++j) {
      if (local[*j] < 0) continue;
      Eigen::Vector3f offset = points[*j] - p;
      offset -= offset.dot(normal) * normal;
      if (side[static_cast<size_t>(local[*j])] == side[v]) {
        own += offset;
        own_distance += offset.norm();
        ++own_count;
      } else {
        other += offset;
      }
    }
    if (own_count < 3 || !(other.norm() > 0.0f) || !(own_distance > 0.0f)) continue;
    bias[side[v]].push_back(-own.dot(other.normalized()) / own_distance);
  }
  for (uint32_t i : cluster) local[i] = -1;
  double largest = 0.0;
  for (auto& values : bias) {
    if (values.size() < min_boundary) return std::numeric_limits<double>::infinity();
    largest = std::max(largest, static_cast<double>(std::abs(UpperMedian(std::move(values)))));
  }
  return largest;
}

}  // namespace

SheetCut SplitOverlappingSheets(const ClusterGraph& graph, const NeighbourLists& neighbours,
                                const std::vector<Eigen::Vector3f>& points,
                                const std::vector<Eigen::Vector3f>& normals,
                                const std::vector<uint32_t>& cluster, const SheetRule& rule,
                                std::vector<int32_t>* scratch) {
  SheetCut result;
  result.edge_bias = std::numeric_limits<double>::infinity();
  const size_t n = cluster.size();
  if (!(rule.max_edge_bias > 0.0) || n < 2 * std::max<size_t>(rule.min_side, 2)) return result;
  std::vector<Eigen::Vector3f> local_normals(n);
  for (size_t v = 0; v < n; ++v) local_normals[v] = normals[cluster[v]];
  const std::vector<float> bends = EdgeBends(graph.edges, local_normals);
  const float smoothing_limit =
      static_cast<float>(rule.smoothing_factor * static_cast<double>(UpperMedian(bends)));
  const std::vector<Eigen::Vector3f> smoothed =
      SmoothedNormals(graph.edges, bends, local_normals, smoothing_limit);
  const SparseGraph weighted = WeightedGraph(
      n, graph.edges, BendWeights(EdgeBends(graph.edges, smoothed), rule.bend_factor));
  const SpectralCut cut =
      LeastConductanceCut(weighted, NormalSpreadStart(points, cluster, local_normals),
                          rule.lanczos_steps, rule.min_side);
  if (cut.size == 0) return result;
  std::vector<uint8_t> side = CutSideOfVertex(cut);
  RefineCut(weighted, rule.refinement_rounds, &side);
  const size_t side_a = static_cast<size_t>(std::count(side.begin(), side.end(), 0));
  if (side_a < rule.min_side || n - side_a < rule.min_side) return result;
  result.edge_bias = EdgeBias(neighbours, points, cluster, graph.edges, side, local_normals,
                              rule.min_side, scratch);
  if (result.edge_bias <= rule.max_edge_bias) result.groups = CutSides(cluster, side);
  return result;
}

}  // namespace avc::cluster
