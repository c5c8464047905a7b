#include "services/surfacer/plant_base.h"

#include <algorithm>

namespace avc::surfacer {

std::optional<double> PlantBaseZ(const mvs::MvsBounds& proxy) {
  if (proxy.empty()) return std::nullopt;
  float lowest = proxy.occupied_centres.front().z();
  for (const Eigen::Vector3f& centre : proxy.occupied_centres)
    lowest = std::min(lowest, centre.z());
  return static_cast<double>(lowest) - 0.5 * proxy.voxel_size;
}

std::optional<double> PlantGroundZ(std::optional<double> soil_z, const mvs::MvsBounds& proxy) {
  return soil_z ? soil_z : PlantBaseZ(proxy);
}

}  // namespace avc::surfacer
