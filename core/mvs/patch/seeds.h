#pragma once

// PMVS seeding: a feature in one image, matched to same-type features near its epipolar line
// in neighbouring images (only where the depth lies in the allowed interval), triangulated,
// tried nearest the camera first; the first candidate that refines into a patch wins.

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/mvs/patch/features.h"
#include "core/mvs/patch/patch.h"
#include "core/mvs/patch/patch_image.h"
#include "core/mvs/patch/patch_refiner.h"

namespace avc::mvs::patch {

class SeedFinder {
 public:
  // features[i]: image i's features; neighbours[i]: the images matched against i;
  // fallback_depths[i]: the depth interval searched in image i where the proxy gives none.
  SeedFinder(const std::vector<PatchImage>& images,
             const std::vector<std::vector<Feature>>& features,
             const std::vector<std::vector<uint32_t>>& neighbours,
             const std::vector<std::pair<double, double>>& fallback_depths,
             const PatchMvsOptions& options);

  // The seed patch of feature f of image i, refined with `refiner`; nullopt when none passes.
  std::optional<Patch> FromFeature(uint32_t image, const Feature& feature,
                                   const PatchRefiner& refiner) const;

 private:
  static constexpr int kBucket = 8;  // pixels per feature bucket side
  struct Buckets {
    int cols = 0, rows = 0;
    std::vector<std::vector<uint32_t>> ids;
  };
  const std::vector<PatchImage>& images_;
  const std::vector<std::vector<Feature>>& features_;
  const std::vector<std::vector<uint32_t>>& neighbours_;
  const std::vector<std::pair<double, double>>& fallback_depths_;
  const PatchMvsOptions& options_;
  std::vector<Buckets> buckets_;
};

}  // namespace avc::mvs::patch
