#include "services/surfacer/plant_base.h"

namespace avc::surfacer {

std::optional<double> PlantBaseZ(const mvs::MvsBounds& proxy) { return proxy.BottomZ(); }

std::optional<double> PlantGroundZ(std::optional<double> soil_z, const mvs::MvsBounds& proxy) {
  return soil_z ? soil_z : PlantBaseZ(proxy);
}

}  // namespace avc::surfacer
