#include "core/cluster/cluster_plant.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/cluster/connected_components.h"
#include "core/cluster/data_scale.h"
#include "core/cluster/divfrp.h"
#include "core/cluster/neck_split.h"
#include "core/cluster/normal_split.h"
#include "core/cluster/pca.h"
#include "core/cluster/point_grid.h"
#include "core/cluster/reassignment.h"
#include "core/cluster/sheet_split.h"
#include "core/cluster/spectral_cut.h"
#include "core/util/validation.h"

namespace avc::cluster {
namespace {

void Require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("ClusterPlant: " + what);
}

// Unit copies of the normals after checking the input.
std::vector<Eigen::Vector3f> CheckedNormals(const PointSet& set) {
  const std::string name = set.name.empty() ? "point set" : "point set '" + set.name + "'";
  Require(set.points.size() >= 3,
          name + " needs at least 3 points, got " + std::to_string(set.points.size()));
  Require(set.normals.size() == set.points.size(),
          name + " needs one normal per point: " + std::to_string(set.normals.size()) +
              " normals for " + std::to_string(set.points.size()) + " points");
  std::vector<Eigen::Vector3f> unit(set.normals.size());
  for (size_t i = 0; i < set.points.size(); ++i) {
    Require(set.points[i].allFinite(), name + ": point " + std::to_string(i) + " is not finite");
    Require(set.normals[i].allFinite(), name + ": normal " + std::to_string(i) + " is not finite");
    const float length = set.normals[i].norm();
    Require(length > 1e-6f, name + ": normal " + std::to_string(i) + " is zero");
    unit[i] = set.normals[i] / length;
  }
  return unit;
}

bool IsFlat(const PrincipalAxes& axes, double noise_tolerance, double flatness_ratio) {
  const double deviation = axes.PlaneDeviation();
  if (deviation <= noise_tolerance) return true;
  const double mid = std::sqrt(std::max(0.0, axes.eigenvalues[1]));
  return deviation <= flatness_ratio * mid;
}

}  // namespace

std::string ClusterOptions::Validate() const {
  const ClusterOptions& o = *this;
  FirstProblem problem;
  const auto Require = [&problem](bool ok, const std::string& what) {
    problem.Require(ok, "ClusterOptions: " + what);
  };
  Require(std::isfinite(o.spacing) && std::isfinite(o.noise), "spacing and noise must be finite");
  Require(o.link_factor > 0 && o.bin_factor > 0 && o.noise_factor >= 0 && o.flatness_ratio >= 0 &&
              o.min_normal_gain >= 0,
          "link_factor and bin_factor must be > 0; noise_factor, flatness_ratio and "
          "min_normal_gain >= 0");
  Require(std::isfinite(o.link_mean_slope), "link_mean_slope must be finite (< 0: not used)");
  Require(std::isfinite(o.tube.min_alignment) && o.tube.min_alignment >= 0 &&
              std::isfinite(o.tube.max_radius_spread) && o.tube.max_radius_spread >= 0,
          "tube.min_alignment and tube.max_radius_spread must be finite and >= 0");
  Require(o.min_cluster_points >= 0 && o.refinement_rounds >= 0 && o.reassignment_rounds >= 0,
          "min_cluster_points, refinement_rounds and reassignment_rounds must be >= 0");
  Require(o.neck_neighbours >= 1 && o.neck_lanczos_steps >= 2 && o.sheet_lanczos_steps >= 2,
          "neck_neighbours must be >= 1, neck_lanczos_steps and sheet_lanczos_steps >= 2");
  Require(std::isfinite(o.max_neck_ratio) && o.max_neck_ratio >= 0 &&
              std::isfinite(o.neck_bend_factor) && o.neck_bend_factor >= 0 &&
              std::isfinite(o.neck_elevation_factor) && o.neck_elevation_factor >= 0 &&
              std::isfinite(o.neck_max_boundary_shift) && o.neck_max_boundary_shift >= 0,
          "max_neck_ratio, neck_bend_factor, neck_elevation_factor and neck_max_boundary_shift "
          "must be finite and >= 0");
  Require(std::isfinite(o.sheet_smoothing_factor) && o.sheet_smoothing_factor >= 0 &&
              std::isfinite(o.sheet_bend_factor) && o.sheet_bend_factor >= 0 &&
              std::isfinite(o.max_sheet_edge_bias) && o.max_sheet_edge_bias >= 0,
          "sheet_smoothing_factor, sheet_bend_factor and max_sheet_edge_bias must be finite and "
          ">= 0");
  return problem.text();
}

Assignment ClusterPlant(const PointSet& set, const ClusterOptions& options, ClusterReport* report) {
  const std::vector<Eigen::Vector3f> normals = CheckedNormals(set);
  RequireValid(options);
  const std::vector<Eigen::Vector3f>& points = set.points;

  ClusterReport local;
  ClusterReport& out = report ? *report : local;
  out = ClusterReport{};
  if (options.spacing > 0 && options.noise > 0) {
    out.spacing = options.spacing;
    out.noise = options.noise;
  } else {
    const DataScale scale = EstimateDataScale(points);
    out.spacing = options.spacing > 0 ? options.spacing : scale.spacing;
    out.noise = options.noise > 0 ? options.noise : scale.noise;
  }
  const float link_radius = static_cast<float>(options.link_factor * out.spacing);
  out.link_radius = link_radius;
  const size_t min_points = options.min_cluster_points > 0
                                ? static_cast<size_t>(options.min_cluster_points)
                                : static_cast<size_t>(std::lround(4.0 * std::numbers::pi));
  out.min_cluster_points = static_cast<int>(min_points);
  const double noise_tolerance = options.noise_factor * out.noise;
  const double bin_width = options.bin_factor * out.spacing;

  const PointGrid grid(points, link_radius);
  LinkRule link;
  link.radius = link_radius;
  link.normals = &normals;
  link.slope = static_cast<float>(options.link_slope);
  link.allowance = static_cast<float>(noise_tolerance);
  link.mean_slope = static_cast<float>(options.link_mean_slope);
  const NeighbourLists neighbours(grid, points, link);
  NeckRule neck_rule;
  neck_rule.neighbours = options.neck_neighbours;
  neck_rule.lanczos_steps = options.neck_lanczos_steps;
  neck_rule.min_side = min_points;
  neck_rule.bend_factor = options.neck_bend_factor;
  neck_rule.max_neck_ratio = options.max_neck_ratio;
  neck_rule.elevation_factor = options.neck_elevation_factor;
  neck_rule.max_boundary_shift = options.neck_max_boundary_shift;
  neck_rule.refinement_rounds = options.refinement_rounds;
  SheetRule sheet_rule;
  sheet_rule.lanczos_steps = options.sheet_lanczos_steps;
  sheet_rule.min_side = min_points;
  sheet_rule.smoothing_factor = options.sheet_smoothing_factor;
  sheet_rule.bend_factor = options.sheet_bend_factor;
  sheet_rule.max_edge_bias = options.max_sheet_edge_bias;
  sheet_rule.refinement_rounds = options.refinement_rounds;
  std::vector<int32_t> scratch(points.size(), -1);
  std::deque<std::vector<uint32_t>> work;
  std::vector<std::vector<uint32_t>> spurious;
  auto enqueue_components = [&](const std::vector<uint32_t>& part) {
    for (auto& component : ConnectedComponents(neighbours, part, &scratch)) {
      if (component.size() < min_points) {
        spurious.push_back(std::move(component));
      } else {
        work.push_back(std::move(component));
      }
    }
  };

  std::vector<uint32_t> all(points.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<uint32_t>(i);
  for (auto& component : ConnectedComponents(neighbours, all, &scratch)) {
    if (component.size() < min_points) {
      out.outliers += component.size();  // isolated from everything: outliers, never merged
    } else {
      work.push_back(std::move(component));
    }
  }
  out.initial_components = work.size();

  std::vector<std::vector<uint32_t>> accepted;
  // Every split removes at least one point from a cluster, so the loop ends; the bound guards it.
  for (size_t guard = 0; !work.empty() && guard < 4 * points.size(); ++guard) {
    std::vector<uint32_t> cluster = std::move(work.front());
    work.pop_front();
    if (cluster.size() < 2 * min_points) {
      accepted.push_back(std::move(cluster));
      continue;
    }
    const PrincipalAxes axes = FitPrincipalAxes(points, cluster);
    if (!IsFlat(axes, noise_tolerance, options.flatness_ratio) &&
        !IsTube(points, normals, cluster, axes, options.tube)) {
      // The bare cut (a plane across lambda_max) need only show half the gain; the refined
      // boundary must show all of it.
      const NormalSplit split =
          SplitByNormals(points, normals, cluster, axes, /*axis_index=*/2, bin_width,
                         0.5 * options.min_normal_gain, options.refinement_rounds);
      if (split.gain >= options.min_normal_gain && split.left.size() >= min_points &&
          split.right.size() >= min_points) {
        ++out.normal_splits;
        enqueue_components(split.left);
        enqueue_components(split.right);
        continue;
      }
    }
    const auto groups =
        SplitByFurthestReference(neighbours, points, cluster, link_radius, &scratch);
    if (!groups.empty()) {
      ++out.separation_splits;
      for (const auto& group : groups) enqueue_components(group);
      continue;
    }
    // Touching groups that neither the normals nor a gap separate: cut at a narrow neck.
    const ClusterGraph graph =
        NeighbourGraph(neighbours, points, cluster, options.neck_neighbours, &scratch);
    const NeckCut neck = SplitAtNeck(graph, points, &normals, cluster, neck_rule);
    if (!neck.groups.empty()) {
      ++out.neck_splits;
      for (const auto& group : neck.groups) enqueue_components(group);
      continue;
    }
    // No neck: blades that cross, cut where the normal field jumps.
    const SheetCut sheets =
        SplitOverlappingSheets(graph, neighbours, points, normals, cluster, sheet_rule, &scratch);
    if (!sheets.groups.empty()) {
      ++out.sheet_splits;
      for (const auto& group : sheets.groups) enqueue_components(group);
      continue;
    }
    accepted.push_back(std::move(cluster));
  }
  for (auto& cluster : work) accepted.push_back(std::move(cluster));

  std::sort(accepted.begin(), accepted.end(),
            [](const auto& a, const auto& b) { return a.front() < b.front(); });
  Assignment assignment(points.size(), kUnassigned);
  for (size_t c = 0; c < accepted.size(); ++c) {
    for (uint32_t i : accepted[c]) assignment[i] = static_cast<int32_t>(c);
  }
  out.outliers += MergeSpuriousGroups(grid, points, spurious, link_radius, &assignment);
  out.reassigned_points = ReassignDistalPoints(grid, points, normals, link_radius,
                                               options.reassignment_rounds, &assignment);
  out.reassigned_points += RejoinStrandedParts(neighbours, min_points, &scratch, &assignment);
  // Reassignment may empty a cluster: renumber by smallest point index, no gaps.
  std::vector<int32_t> renumber(accepted.size(), kUnassigned);
  int32_t next_id = 0;
  for (int32_t& id : assignment) {
    if (id == kUnassigned) continue;
    int32_t& mapped = renumber[static_cast<size_t>(id)];
    if (mapped == kUnassigned) mapped = next_id++;
    id = mapped;
  }
  out.clusters = static_cast<size_t>(next_id);
  return assignment;
}

}  // namespace avc::cluster
