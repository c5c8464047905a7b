#pragma once

// Where the plant's height is measured from: the base of its proxy. The plant masks leave the
// pot and soil out, so the proxy carved from them ends where the stem leaves the soil, while
// the mesh ends wherever multi-view stereo stopped finding the stem (on the simulated broadleaf
// 37 % of the plant's height above its base).

#include <optional>

#include "core/mvs/mvs_bounds.h"

namespace avc::surfacer {

// The bottom of the proxy's lowest occupied voxel (m, world z); nullopt for an empty proxy.
std::optional<double> PlantBaseZ(const mvs::MvsBounds& proxy);

}  // namespace avc::surfacer
