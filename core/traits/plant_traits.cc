#include "core/traits/plant_traits.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/traits/convex_hull_volume.h"

namespace avc::traits {
namespace {

// Largest distance between two points of the horizontal projection: the diameter of its 2-D
// convex hull (monotone chain), found by checking every hull vertex pair (hulls are small).
double HorizontalWidth(const std::vector<Eigen::Vector3f>& vertices) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(vertices.size());
  for (const Eigen::Vector3f& v : vertices) points.emplace_back(v.x(), v.y());
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 2) return 0.0;
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  double widest = 0.0;
  for (size_t i = 0; i < hull.size(); ++i) {
    for (size_t j = i + 1; j < hull.size(); ++j)
      widest = std::max(widest, (hull[i] - hull[j]).norm());
  }
  return widest;
}

ClusterTraits Orientation(int32_t cluster, double area, const Eigen::Vector3d& normal_sum) {
  ClusterTraits traits;
  traits.cluster = cluster;
  traits.area = area;
  if (normal_sum.norm() > 0.0) traits.normal = normal_sum.normalized();
  traits.inclination = std::acos(std::clamp(traits.normal.z(), -1.0, 1.0));
  const double horizontal = std::hypot(traits.normal.x(), traits.normal.y());
  if (horizontal > 1e-12) {
    traits.azimuth = std::atan2(traits.normal.y(), traits.normal.x());
    if (traits.azimuth < 0.0) traits.azimuth += 2.0 * std::numbers::pi;
  }
  return traits;
}

}  // namespace

PlantTraits MeasureTraits(const geometry::Mesh& mesh, const TraitOptions& options) {
  if (const std::string problem = mesh.Validate(); !problem.empty()) {
    throw std::invalid_argument("traits: mesh: " + problem);
  }
  if (options.ground_z && !std::isfinite(*options.ground_z)) {
    throw std::invalid_argument("traits: ground_z is not finite");
  }
  PlantTraits traits;
  traits.faces = mesh.faces.size();
  if (mesh.faces.empty()) return traits;

  // Only vertices on faces count (a mesh may carry unused ones).
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const Eigen::Vector3i& t : mesh.faces) used[t[0]] = used[t[1]] = used[t[2]] = true;
  std::vector<Eigen::Vector3f> points;
  for (size_t v = 0; v < used.size(); ++v) {
    if (used[v]) points.push_back(mesh.vertices[v]);
  }
  double lowest = points[0].z();
  double highest = points[0].z();
  for (const Eigen::Vector3f& p : points) {
    lowest = std::min(lowest, static_cast<double>(p.z()));
    highest = std::max(highest, static_cast<double>(p.z()));
  }
  traits.height_base_z = options.ground_z.value_or(lowest);
  traits.height = std::max(0.0, highest - traits.height_base_z);
  traits.width = HorizontalWidth(points);
  traits.hull_volume = ConvexHullVolume(points);

  std::map<int32_t, double> cluster_area;
  std::map<int32_t, Eigen::Vector3d> cluster_normal;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
    const Eigen::Vector3d cross =
        (mesh.vertices[t[1]].cast<double>() - a).cross(mesh.vertices[t[2]].cast<double>() - a);
    const double area = 0.5 * cross.norm();
    traits.total_area += area;
    const int32_t cluster = mesh.face_labels.empty() ? 0 : mesh.face_labels[f];
    cluster_area[cluster] += area;
    auto [it, inserted] = cluster_normal.try_emplace(cluster, Eigen::Vector3d::Zero());
    it->second += 0.5 * cross;  // area-weighted
  }
  std::map<int32_t, GroupTraits> groups;
  for (const auto& [cluster, area] : cluster_area) {
    traits.clusters.push_back(Orientation(cluster, area, cluster_normal[cluster]));
    const auto listed = options.group_of_cluster.find(cluster);
    const int32_t group = listed == options.group_of_cluster.end() ? cluster : listed->second;
    GroupTraits& entry = groups[group];
    entry.group = group;
    entry.area += area;
    entry.clusters.push_back(cluster);
  }
  for (auto& [group, entry] : groups) traits.groups.push_back(std::move(entry));
  traits.curvature = SummarizeMeanCurvature(mesh);
  return traits;
}

}  // namespace avc::traits
