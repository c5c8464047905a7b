#pragma once

// The plant's space as the arm must avoid it. The plant turns under an arm that waits (the arm
// moves, then the turntable), so what the arm must clear is the plant swept about the turntable
// axis: a solid of revolution, kept as the largest distance from the axis per height slab. It
// lives in the table frame (z on the axis, origin on it, as a calibration defines it); points
// are checked there, so a table axis tilted against the robot base costs nothing.

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace avc::kinematics {

struct PlantKeepOut {
  static constexpr int kMaxSlabs = 1024;

  Eigen::Isometry3d T_base_table = Eigen::Isometry3d::Identity();
  double z0_m = 0;               // table-frame z of slab 0's bottom
  double slab_m = 0.02;          // slab s spans [z0 + s * slab, z0 + (s + 1) * slab)
  std::vector<double> radius_m;  // per slab: the arm stays at least this far from the axis

  // Empty when usable (finite, rigid transform, slab > 0, radii >= 0, at most kMaxSlabs), else
  // what is wrong.
  std::string Validate() const;
  bool empty() const { return radius_m.empty(); }
  // Strictly closer to the axis than its slab's radius.
  bool Contains(const Eigen::Vector3d& p_base) const;
  // p's distance from the axis and its slab's radius (0 outside every slab).
  double AxisDistance(const Eigen::Vector3d& p_base) const;
  double RadiusAt(const Eigen::Vector3d& p_base) const;
};

// The keep-out of voxels (centres in the plant frame = table frame at angle 0, edge voxel_m)
// swept about the table's z axis and grown by margin_m outwards and up and down. No voxels: an
// empty keep-out. Throws std::invalid_argument for a non-finite centre or transform, a voxel
// or slab that is not positive, a negative margin, or more than kMaxSlabs slabs.
PlantKeepOut PlantKeepOutFromVoxels(const std::vector<Eigen::Vector3f>& centres_world,
                                    double voxel_m, const Eigen::Isometry3d& T_base_table,
                                    double margin_m, double slab_m = 0.02);

}  // namespace avc::kinematics
