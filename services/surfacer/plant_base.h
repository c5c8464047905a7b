#pragma once

// Where the plant's height is measured from. Best: the soil surface the builder found in the
// images (services/builder/soil_level.h). Without it: the base of the proxy. The plant masks
// leave the pot and soil out, so the proxy carved from them ends near where the stem leaves the
// soil (3-4 mm under it on the simulated scans, 12 mm above it where extra views lose the stem
// base), while the mesh ends wherever multi-view stereo stopped finding the stem (on the
// simulated broadleaf 37 % of the plant's height above its base).

#include <optional>

#include "core/mvs/mvs_bounds.h"

namespace avc::surfacer {

// The bottom of the proxy's lowest occupied voxel (m, world z); nullopt for an empty proxy.
std::optional<double> PlantBaseZ(const mvs::MvsBounds& proxy);

// soil_z when known, else PlantBaseZ(proxy).
std::optional<double> PlantGroundZ(std::optional<double> soil_z, const mvs::MvsBounds& proxy);

}  // namespace avc::surfacer
