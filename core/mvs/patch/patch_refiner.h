#pragma once

// The photometric heart of PMVS: sampling a patch in an image, its NCC with the reference, the
// images that should see it (V) and those that agree (V*), and the 3-DoF refinement (depth
// along the reference ray, two normal angles) that turns a rough guess into an accepted patch.

#include <cstdint>
#include <vector>

#include "core/mvs/occupancy_lookup.h"
#include "core/mvs/patch/cell_grid.h"
#include "core/mvs/patch/patch.h"
#include "core/mvs/patch/patch_image.h"
#include "core/mvs/patch/patch_mvs.h"

namespace avc::mvs::patch {

class PatchRefiner {
 public:
  // Keeps references: all must outlive the refiner. `grids` is read only (a frozen snapshot
  // while a wave runs in parallel).
  PatchRefiner(const std::vector<PatchImage>& images, const CellGrids& grids,
               const OccupancyLookup& lookup, const PatchMvsOptions& options);

  // V(p): images where the centre projects inside and usable, the normal faces the camera
  // within the angle limit, and no registered patch lies clearly in front. Sorted.
  std::vector<uint32_t> VisibleImages(const Patch& patch) const;

  // Optimises `patch` (centre, normal and reference set on entry) and fills its V* and score.
  // False when it fails: too few agreeing images, untextured, outside the proxy.
  bool Refine(Patch* patch) const;

 private:
  struct Frame;  // the patch's sampling grid geometry
  bool MakeFrame(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, uint32_t ref,
                 Frame* frame) const;
  // Samples the μ x μ grid in one image into out (3 μ² floats), normalised to zero mean and
  // unit length; false when it leaves the image or has no texture.
  bool SampleNormalised(const Frame& frame, uint32_t image, float* out, double min_deviation) const;

  const std::vector<PatchImage>& images_;
  const CellGrids& grids_;
  const OccupancyLookup& lookup_;
  const PatchMvsOptions& options_;
  double cos_max_angle_;
};

}  // namespace avc::mvs::patch
