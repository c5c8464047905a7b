#include "core/surface/triangulate_cell.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/cluster/pca.h"
#include "core/surface/circumradius.h"
#include "core/surface/delaunay_2d.h"

namespace avc::surface {
namespace {

// The regression plane, its normal turned towards the points' normals (or up when they have
// none or cancel out), its first axis the cluster's longest.
PlaneFrame RegressionPlane(const ClusteredPoints& input, const std::vector<uint32_t>& members,
                           const cluster::PrincipalAxes& axes) {
  Eigen::Vector3d normal = axes.PlaneNormal();
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();
  for (uint32_t i : members) {
    if (!input.cloud.normals.empty()) normal_sum += input.cloud.normals[i].cast<double>();
  }
  const double agreement = normal.dot(normal_sum);
  if (agreement < 0.0 || (agreement == 0.0 && normal.z() < 0.0)) normal = -normal;
  return MakePlaneFrame(axes.centroid, normal, axes.LongestAxis());
}

constexpr double kClearlyFlatter = 0.5;

using Halves = std::pair<std::vector<uint32_t>, std::vector<uint32_t>>;

// Splits members (ascending) at the median of key(point index), both halves ascending.
template <class Key>
Halves SplitAtMedian(const std::vector<uint32_t>& members, const Key& key) {
  std::vector<std::pair<double, uint32_t>> order;
  order.reserve(members.size());
  for (uint32_t i : members) order.emplace_back(key(i), i);
  std::sort(order.begin(), order.end());
  Halves halves;
  for (size_t k = 0; k < order.size(); ++k) {
    (k < order.size() / 2 ? halves.first : halves.second).push_back(order[k].second);
  }
  std::sort(halves.first.begin(), halves.first.end());
  std::sort(halves.second.begin(), halves.second.end());
  return halves;
}

// Sum of squared distances of both halves to their own regression planes.
double PlaneResidual(const ClusteredPoints& input, const Halves& halves) {
  double residual = 0.0;
  for (const std::vector<uint32_t>* half : {&halves.first, &halves.second}) {
    const cluster::PrincipalAxes axes = cluster::FitPrincipalAxes(input.cloud.positions, *half);
    residual += static_cast<double>(half->size()) * std::max(0.0, axes.eigenvalues[0]);
  }
  return residual;
}

// The median split, across one of the principal axes or across the main spread of the
// normals, that leaves the two halves flattest (the clusterer's normal constraint): across
// the longest axis for an arching leaf, across the normal for layers, by normal for leaves
// meeting at an angle.
Halves FlattestSplit(const ClusteredPoints& input, const std::vector<uint32_t>& members,
                     const cluster::PrincipalAxes& axes) {
  std::vector<Halves> candidates;
  for (int axis = 2; axis >= 0; --axis) {
    const Eigen::Vector3d direction = axes.axes.col(axis);
    candidates.push_back(SplitAtMedian(members, [&](uint32_t i) {
      return input.cloud.positions[i].cast<double>().dot(direction);
    }));
  }
  if (!input.cloud.normals.empty()) {
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (uint32_t i : members) mean += input.cloud.normals[i].cast<double>();
    mean /= static_cast<double>(members.size());
    for (uint32_t i : members) {
      const Eigen::Vector3d d = input.cloud.normals[i].cast<double>() - mean;
      spread += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(spread);
    const Eigen::Vector3d direction = solver.eigenvectors().col(2);
    candidates.push_back(SplitAtMedian(
        members, [&](uint32_t i) { return input.cloud.normals[i].cast<double>().dot(direction); }));
  }
  // Across the longest axis unless another split is clearly flatter: halves across a narrow
  // direction are thin strips that triangulate poorly.
  size_t best = 0;
  double best_residual = kClearlyFlatter * PlaneResidual(input, candidates[0]);
  for (size_t k = 1; k < candidates.size(); ++k) {
    const double residual = PlaneResidual(input, candidates[k]);
    if (residual < best_residual) {
      best_residual = residual;
      best = k;
    }
  }
  return std::move(candidates[best]);
}

}  // namespace

Cell TriangulateCell(const ClusteredPoints& input, int32_t cluster,
                     const std::vector<uint32_t>& members, double alpha, std::string* problem,
                     size_t* steep_faces) {
  if (steep_faces != nullptr) *steep_faces = 0;
  Cell cell;
  cell.cluster = cluster;
  auto warn = [&](const std::string& why) {
    if (problem != nullptr) *problem = why;
  };
  if (members.size() < 3) {
    warn("fewer than 3 points, nothing to triangulate");
    return cell;
  }
  const cluster::PrincipalAxes axes = cluster::FitPrincipalAxes(input.cloud.positions, members);
  // Spread across the line below 1e-6 of the spread along it (relative, so any unit works):
  // collinear, no plane to project on.
  if (!(axes.eigenvalues[1] > 1e-12 * axes.eigenvalues[2])) {
    warn(axes.eigenvalues[2] > 0.0 ? "the points are collinear" : "all points coincide");
    return cell;
  }
  cell.plane = RegressionPlane(input, members, axes);

  std::vector<Eigen::Vector2d> projected;
  projected.reserve(members.size());
  for (uint32_t i : members) projected.push_back(cell.plane.Project(input.cloud.positions[i]));

  // (u, v, normal) is right-handed, so counter-clockwise on the plane faces along the normal.
  // A triangle small on the plane but large once lifted spans a fold or two layers: steep.
  auto lifted = [&](int k) { return input.cloud.positions[members[k]].cast<double>(); };
  for (const Eigen::Vector3i& t : Delaunay2d(projected)) {
    if (Circumradius<2>(projected[t[0]], projected[t[1]], projected[t[2]]) > alpha) continue;
    if (Circumradius<3>(lifted(t[0]), lifted(t[1]), lifted(t[2])) > alpha) {
      if (steep_faces != nullptr) ++*steep_faces;
      continue;
    }
    cell.mesh.faces.push_back(t);
  }
  if (cell.mesh.faces.empty()) {
    warn(fmt::format("no Delaunay triangle has a circumradius within alpha = {:.3g} m", alpha));
    return cell;
  }
  const bool coloured = !input.cloud.colors.empty();
  for (uint32_t i : members) {
    cell.mesh.vertices.push_back(input.cloud.positions[i]);
    if (coloured) cell.mesh.colors.push_back(input.cloud.colors[i]);
    cell.source_points.push_back(static_cast<int32_t>(i));
  }
  cell.mesh.face_labels.assign(cell.mesh.faces.size(), cluster);
  return cell;
}

std::vector<Cell> TriangulateSurfacePiece(const ClusteredPoints& input, int32_t cluster,
                                          const std::vector<uint32_t>& members, double alpha,
                                          std::string* problem, int max_depth) {
  size_t steep = 0;
  Cell cell = TriangulateCell(input, cluster, members, alpha, problem, &steep);
  const size_t kept = cell.mesh.faces.size();
  const bool folded = steep > 0 && static_cast<double>(steep) >
                                       kMaxSteepFraction * static_cast<double>(steep + kept);
  if (!folded || max_depth <= 0 || members.size() < 2 * kMinSplitPoints) {
    std::vector<Cell> cells;
    if (kept > 0) cells.push_back(std::move(cell));
    return cells;
  }
  const cluster::PrincipalAxes axes = cluster::FitPrincipalAxes(input.cloud.positions, members);
  const auto [first, second] = FlattestSplit(input, members, axes);
  std::vector<Cell> cells =
      TriangulateSurfacePiece(input, cluster, first, alpha, problem, max_depth - 1);
  for (Cell& more :
       TriangulateSurfacePiece(input, cluster, second, alpha, problem, max_depth - 1)) {
    cells.push_back(std::move(more));
  }
  return cells;
}

}  // namespace avc::surface
