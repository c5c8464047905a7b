#include "core/kinematics/plant_keep_out.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/geometry/rigid_transform.h"

namespace avc::kinematics {
namespace {

// -1 below slab 0, size() above the last.
int SlabOf(const PlantKeepOut& k, double z_table) {
  const double s = std::floor((z_table - k.z0_m) / k.slab_m);
  if (!(s >= 0)) return -1;
  return s >= static_cast<double>(k.radius_m.size()) ? static_cast<int>(k.radius_m.size())
                                                     : static_cast<int>(s);
}

}  // namespace

std::string PlantKeepOut::Validate() const {
  if (auto problem = geometry::RigidTransformProblem(T_base_table, "plant keep-out: T_base_table");
      !problem.empty()) {
    return problem;
  }
  if (!std::isfinite(z0_m) || !(slab_m > 0) || !std::isfinite(slab_m)) {
    return fmt::format("plant keep-out: z0 {} m and slab {} m must be finite, slab > 0", z0_m,
                       slab_m);
  }
  if (radius_m.size() > kMaxSlabs) {
    return fmt::format("plant keep-out: {} slabs, at most {}", radius_m.size(), kMaxSlabs);
  }
  for (size_t s = 0; s < radius_m.size(); ++s) {
    if (!(radius_m[s] >= 0) || !std::isfinite(radius_m[s])) {
      return fmt::format("plant keep-out: slab {} radius {} m is not finite and >= 0", s,
                         radius_m[s]);
    }
  }
  return {};
}

double PlantKeepOut::AxisDistance(const Eigen::Vector3d& p_base) const {
  return (T_base_table.inverse() * p_base).head<2>().norm();
}

double PlantKeepOut::RadiusAt(const Eigen::Vector3d& p_base) const {
  const int s = SlabOf(*this, (T_base_table.inverse() * p_base).z());
  return s >= 0 && s < static_cast<int>(radius_m.size()) ? radius_m[s] : 0.0;
}

bool PlantKeepOut::Contains(const Eigen::Vector3d& p_base) const {
  return AxisDistance(p_base) < RadiusAt(p_base);
}

PlantKeepOut PlantKeepOutFromVoxels(const std::vector<Eigen::Vector3f>& centres_world,
                                    double voxel_m, const Eigen::Isometry3d& T_base_table,
                                    double margin_m, double slab_m) {
  if (!geometry::RigidTransformProblem(T_base_table, "").empty() || !(voxel_m > 0) ||
      !std::isfinite(voxel_m) || !(margin_m >= 0) || !std::isfinite(margin_m) || !(slab_m > 0) ||
      !std::isfinite(slab_m)) {
    throw std::invalid_argument(
        "PlantKeepOutFromVoxels: needs a rigid transform, voxel and slab > 0 and margin >= 0");
  }
  PlantKeepOut keep_out;
  keep_out.T_base_table = T_base_table;
  keep_out.slab_m = slab_m;
  if (centres_world.empty()) return keep_out;
  // Turning about z keeps a point's height and distance from the axis. A voxel reaches half its
  // edge up and down and half its diagonal (edge / sqrt 2) beyond its centre's distance.
  const double half_height = voxel_m / 2 + margin_m;
  const double reach = voxel_m / std::sqrt(2.0) + margin_m;
  double z_low = std::numeric_limits<double>::infinity();
  double z_high = -z_low;
  for (const Eigen::Vector3f& c : centres_world) {
    if (!c.allFinite()) throw std::invalid_argument("PlantKeepOutFromVoxels: non-finite voxel");
    z_low = std::min(z_low, c.z() - half_height);
    z_high = std::max(z_high, c.z() + half_height);
  }
  const double slabs = std::ceil((z_high - z_low) / slab_m);
  if (slabs > PlantKeepOut::kMaxSlabs) {
    throw std::invalid_argument(fmt::format(
        "PlantKeepOutFromVoxels: {:.2f} m of height in {} m slabs is more than {} slabs",
        z_high - z_low, slab_m, PlantKeepOut::kMaxSlabs));
  }
  keep_out.z0_m = z_low;
  keep_out.radius_m.assign(std::max(1, static_cast<int>(slabs)), 0.0);
  const int last = static_cast<int>(keep_out.radius_m.size()) - 1;
  for (const Eigen::Vector3f& c : centres_world) {
    const double radius = c.head<2>().cast<double>().norm() + reach;
    const int first = std::clamp(SlabOf(keep_out, c.z() - half_height), 0, last);
    // The slab holding the top, itself excluded (a top on a slab boundary adds no slab above).
    const double top = (c.z() + half_height - keep_out.z0_m) / slab_m;
    const int end = std::clamp(static_cast<int>(std::ceil(top)) - 1, first, last);
    for (int s = first; s <= end; ++s) {
      keep_out.radius_m[s] = std::max(keep_out.radius_m[s], radius);
    }
  }
  return keep_out;
}

}  // namespace avc::kinematics
