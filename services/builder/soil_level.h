#pragma once

// Where the plant stands: the height of the soil surface around its stem, found from the images.
// Plant height is measured from there. The masks leave pot and soil out, so the proxy's lowest
// voxel only approximates it: on the simulated scans it ends 3-4 mm under the soil (the stem's
// base is seen by few views, so its hull widens downwards), on an active-vision scan whose extra
// views lose the thin stem base in their masks 12 mm above it.
//
// The soil is textured and seen between the leaves. Horizontal planes are swept over heights
// around the proxy's base; on each, small square patches on an annulus around the stem are
// projected into every view whose mask shows background over the whole patch, and the views'
// patches are compared by normalised cross-correlation. On the soil's own height they agree; above
// or below it each view sees other grains. Patches without texture (the pot's plain inner wall,
// which a plane above the soil meets in the far views) have no say: a plain colour agrees at any
// height. The plane of best median agreement wins when it stands out from the rest.

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/dataset/view.h"
#include "core/mvs/mvs_bounds.h"

namespace avc::builder {

struct SoilLevelOptions {
  bool enabled = true;
  double inner_radius = 0.015;    // m from the stem: inside, the stem and its base hide the soil
  double outer_radius = 0.055;    // m: inside a small pot's rim (75 mm for the simulated one)
  double sample_spacing = 0.002;  // m between patch centres on the annulus
  double search_below = 0.03;     // m below the proxy's base
  double search_above = 0.03;     // m above it
  double coarse_step = 0.0015;    // m between planes of the first sweep
  double fine_step = 0.00025;     // m between planes of the second, around the first's best
  int min_views = 3;              // per patch, seeing textured background all over it
  // Only views looking down on a patch at least this steeply (degrees above the horizon) count:
  // from lower, the pot's rim hides the soil and the views see its wall instead.
  double min_elevation_deg = 30.0;
  int min_patches = 100;  // per plane, with enough views
  // The winning plane's median disagreement (1 - correlation) must be at most this fraction of
  // the median over the first sweep's planes; a flat sweep means no soil was seen.
  double max_contrast = 0.6;

  // Empty when valid; else a sentence naming the bad field (SoilLevelOptions.<field>).
  std::string Validate() const;
};

struct SoilLevel {
  double z = 0;         // m, world
  double contrast = 0;  // winning plane's median disagreement / median over the planes
  size_t patches = 0;   // patches seen by enough views on the winning plane
};

// views: undistorted, with plant masks. The stem is taken at the proxy's base: the centroid of its
// occupied voxels within 10 mm of the lowest. nullopt when disabled, the proxy is empty, too few
// patches are seen, or no plane stands out; `why_not` (optional) then gets a sentence saying
// which. Throws std::invalid_argument for bad options.
std::optional<SoilLevel> FindSoilLevel(const std::vector<dataset::View>& views,
                                       const mvs::MvsBounds& proxy,
                                       const SoilLevelOptions& options = {},
                                       std::string* why_not = nullptr);

// The soil's height when found.
inline std::optional<double> SoilZ(const std::optional<SoilLevel>& soil) {
  return soil ? std::optional<double>(soil->z) : std::nullopt;
}

nlohmann::ordered_json SoilLevelToJson(const SoilLevel& soil);
// soil.json as WriteReconstruction writes it; nullopt when the file is absent. Throws
// std::runtime_error naming the file when it cannot be parsed.
std::optional<SoilLevel> ReadSoilLevel(const std::filesystem::path& file);

}  // namespace avc::builder
