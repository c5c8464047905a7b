#include "core/mvs/view_neighbours.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace avc::mvs {

std::vector<std::vector<uint32_t>> SelectNeighbours(const std::vector<camera::Camera>& cameras,
                                                    const Eigen::Vector3d& scene_centre,
                                                    const NeighbourOptions& options) {
  const size_t n = cameras.size();
  std::vector<Eigen::Vector3d> to_centre(n);
  std::vector<bool> sees_centre(n);
  for (size_t i = 0; i < n; ++i) {
    to_centre[i] = (scene_centre - cameras[i].Centre()).normalized();
    sees_centre[i] = (cameras[i].T_cam_world * scene_centre).z() > 0;
  }
  std::vector<std::vector<uint32_t>> neighbours(n);
  for (size_t i = 0; i < n; ++i) {
    if (!sees_centre[i]) continue;
    // Ranked by the distance from the preferred angle, quantised to 1e-9 rad so that views
    // symmetric about this one tie exactly (then the lower index wins) whatever the rounding.
    std::vector<std::pair<int64_t, uint32_t>> ranked;
    for (size_t j = 0; j < n; ++j) {
      if (j == i || !sees_centre[j]) continue;
      const double angle = std::acos(std::clamp(to_centre[i].dot(to_centre[j]), -1.0, 1.0));
      if (angle < options.min_angle || angle > options.max_angle) continue;
      ranked.emplace_back(std::llround(1e9 * std::abs(angle - options.preferred_angle)),
                          static_cast<uint32_t>(j));
    }
    std::sort(ranked.begin(), ranked.end());
    const size_t keep = std::min(ranked.size(), static_cast<size_t>(options.max_neighbours));
    for (size_t r = 0; r < keep; ++r) neighbours[i].push_back(ranked[r].second);
  }
  return neighbours;
}

Eigen::Vector3d NearestPointToAxes(const std::vector<camera::Camera>& cameras) {
  // Minimise the summed squared distance to the lines c + s a: sum (I - a a^T) (x - c) = 0.
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_axis = Eigen::Vector3d::Zero();
  for (const camera::Camera& camera : cameras) {
    const Eigen::Vector3d a = camera.Axis();
    const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - a * a.transpose();
    normal_matrix += projector;
    rhs += projector * camera.Centre();
    mean_centre += camera.Centre();
    mean_axis += a;
  }
  if (cameras.empty()) return Eigen::Vector3d::Zero();
  mean_centre /= static_cast<double>(cameras.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(normal_matrix);
  if (eigen.eigenvalues()(0) < 1e-6 * static_cast<double>(cameras.size())) {
    return mean_centre + mean_axis.normalized();
  }
  return normal_matrix.ldlt().solve(rhs);
}

}  // namespace avc::mvs
