#include "services/builder/support_level.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "core/util/upper_median.h"
#include "core/util/validation.h"

namespace avc::builder {

std::string SupportOptions::Validate() const {
  if (!(min_jump > 1)) return "SupportOptions.min_jump must be above 1";
  if (!(min_mass_fraction >= 0 && min_mass_fraction <= 1)) {
    return "SupportOptions.min_mass_fraction must be in [0, 1]";
  }
  if (min_plant_slices < 1) {
    return "SupportOptions.min_plant_slices must be at least 1";
  }
  return {};
}

std::optional<SupportTop> FindSupportTop(const std::vector<Eigen::Vector3f>& occupied,
                                         double voxel_size, const SupportOptions& options) {
  RequireValid(options);
  if (!options.enabled || occupied.empty() || !(voxel_size > 0)) return std::nullopt;
  std::map<int64_t, double> slices;  // slice index (z / voxel) -> voxels
  for (const Eigen::Vector3f& centre : occupied) {
    slices[static_cast<int64_t>(std::floor(centre.z() / voxel_size))] += 1;
  }
  const double total = static_cast<double>(occupied.size());
  double at_or_below = total;
  std::vector<double> above;
  for (auto slice = slices.rbegin(); slice != slices.rend(); ++slice) {
    const double count = slice->second;
    if (static_cast<int>(above.size()) >= options.min_plant_slices) {
      const double jump = count / UpperMedian(above);
      const double mass = at_or_below / total;
      if (jump >= options.min_jump && mass >= options.min_mass_fraction) {
        return SupportTop{(static_cast<double>(slice->first) + 1) * voxel_size, jump, mass};
      }
    }
    above.push_back(count);
    at_or_below -= count;
  }
  return std::nullopt;
}

std::string DescribeSupport(const SupportTop& support) {
  return fmt::format(
      "support found under the plant: top at z = {:.1f} mm ({:.0f}x the plant's slices, {:.0f} % "
      "of the proxy); the proxy is cut there and plant height measured from it",
      support.z * 1e3, support.jump, 100 * support.mass_fraction);
}

}  // namespace avc::builder
