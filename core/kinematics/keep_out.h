#pragma once

// A fixed keep-out volume for the arm's checked points (the turntable and what stands on it, as
// configured): a vertical cylinder in the robot's base frame. The plant's own, which follows
// its proxy, is plant_keep_out.h.

#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace avc::kinematics {

struct KeepOutCylinder;
// "x y radius z_min z_max" (base frame, m; shortest text that reads back to the same doubles),
// the cylinder's form in settings and configuration files.
std::string KeepOutText(const KeepOutCylinder& cylinder);
// That text back as the cylinder; nullopt when it is not five numbers.
std::optional<KeepOutCylinder> ParseKeepOut(const std::string& text);

struct KeepOutCylinder {
  Eigen::Vector2d centre_base = Eigen::Vector2d::Zero();  // vertical axis through (x, y), base
  double radius_m = 0;
  double z_min_m = 0;  // base z range the cylinder spans
  double z_max_m = 0;

  // Empty when usable (finite, radius >= 0, z_min <= z_max), else what is wrong.
  std::string Validate() const;
  // Strictly within the radius and within the z range (the boundary is outside).
  bool Contains(const Eigen::Vector3d& p_base) const;
  // Distance of p from the axis in the base xy plane.
  double RadialDistance(const Eigen::Vector3d& p_base) const;
};

}  // namespace avc::kinematics
