#include "sim/cell/perturbation.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "sim/cell/random.h"

namespace avc::sim {
namespace {

// A rotation by an angle uniform in [0, max_angle] about a uniformly random axis.
Eigen::Matrix3d RandomRotation(DeterministicRandom& random, double max_angle) {
  const Eigen::Vector3d axis = random.UnitVector();
  return Eigen::AngleAxisd(random.Uniform(0, max_angle), axis).toRotationMatrix();
}

Eigen::Vector3d RandomOffset(DeterministicRandom& random, double half_width) {
  const double x = random.Symmetric(half_width);
  const double y = random.Symmetric(half_width);
  const double z = random.Symmetric(half_width);
  return {x, y, z};
}

// Applies a rotation and translation perturbation to a pose given in its parent frame.
Eigen::Isometry3d Perturb(const Eigen::Isometry3d& pose, DeterministicRandom& random,
                          double max_angle, double half_width) {
  Eigen::Isometry3d perturbed = pose;
  perturbed.linear() = RandomRotation(random, max_angle) * pose.linear();
  perturbed.translation() += RandomOffset(random, half_width);
  return perturbed;
}

}  // namespace

std::string PerturbationScales::Validate() const {
  const std::pair<const char*, double> fields[] = {
      {"dh_length_m", dh_length_m},
      {"dh_alpha_rad", dh_alpha_rad},
      {"dh_theta_offset_rad", dh_theta_offset_rad},
      {"base_translation_m", base_translation_m},
      {"base_rotation_rad", base_rotation_rad},
      {"axis_tilt_rad", axis_tilt_rad},
      {"centre_offset_m", centre_offset_m},
      {"hand_eye_translation_m", hand_eye_translation_m},
      {"hand_eye_rotation_rad", hand_eye_rotation_rad},
      {"focal_relative", focal_relative},
      {"principal_point_px", principal_point_px},
      {"k1_k2", k1_k2},
      {"k3", k3},
      {"p1_p2", p1_p2}};
  for (const auto& [name, value] : fields) {
    if (!(std::isfinite(value) && value >= 0)) {
      return fmt::format("perturbation scale {} = {} must be finite and non-negative", name, value);
    }
  }
  if (focal_relative >= 0.5) return "perturbation scale focal_relative must be below 0.5";
  return {};
}

CellTruth PerturbedCell(uint32_t seed, const PerturbationScales& scales) {
  if (std::string error = scales.Validate(); !error.empty()) {
    throw std::invalid_argument("PerturbedCell: " + error);
  }
  DeterministicRandom random(seed);
  CellTruth cell = NominalCell();
  // The draw order below is part of the seed's meaning: append new draws at the end.
  for (int i = 0; i < 6; ++i) {
    cell.dh.a[i] += random.Symmetric(scales.dh_length_m);
    cell.dh.d[i] += random.Symmetric(scales.dh_length_m);
    cell.dh.alpha[i] += random.Symmetric(scales.dh_alpha_rad);
    cell.dh.theta_offset[i] += random.Symmetric(scales.dh_theta_offset_rad);
  }
  // The robot base is placed on the table, so its error lives in the table frame.
  const Eigen::Isometry3d T_table_base = Perturb(
      cell.T_base_table.inverse(), random, scales.base_rotation_rad, scales.base_translation_m);
  cell.T_base_table = T_table_base.inverse();

  // Tilt the axis by up to axis_tilt_rad towards a uniformly random horizontal direction.
  const double tilt = random.Uniform(0, scales.axis_tilt_rad);
  const double tilt_direction = random.Uniform(0, 2 * std::numbers::pi);
  const Eigen::Vector3d tilt_axis(-std::sin(tilt_direction), std::cos(tilt_direction), 0);
  cell.turntable_axis_table = Eigen::AngleAxisd(tilt, tilt_axis) * Eigen::Vector3d::UnitZ();
  const double centre_x = random.Symmetric(scales.centre_offset_m);
  const double centre_y = random.Symmetric(scales.centre_offset_m);
  cell.turntable_centre_table = Eigen::Vector3d(centre_x, centre_y, 0);

  // The camera's mounting error is expressed in the flange frame.
  cell.T_flange_cam = Perturb(cell.T_flange_cam, random, scales.hand_eye_rotation_rad,
                              scales.hand_eye_translation_m);

  camera::Intrinsics& k = cell.intrinsics;
  k.fx *= 1 + random.Symmetric(scales.focal_relative);
  k.fy *= 1 + random.Symmetric(scales.focal_relative);
  k.cx += random.Symmetric(scales.principal_point_px);
  k.cy += random.Symmetric(scales.principal_point_px);
  k.distortion[0] += random.Symmetric(scales.k1_k2);
  k.distortion[1] += random.Symmetric(scales.k1_k2);
  k.distortion[2] += random.Symmetric(scales.p1_p2);
  k.distortion[3] += random.Symmetric(scales.p1_p2);
  k.distortion[4] += random.Symmetric(scales.k3);
  return cell;
}

}  // namespace avc::sim
