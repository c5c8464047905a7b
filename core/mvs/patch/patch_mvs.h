#pragma once

// Patch-based multi-view stereo in the spirit of PMVS (Furukawa & Ponce 2010): oriented patches
// seeded from matched Harris / DoG features inside the masks (epipolar search bounded by the
// plant proxy), refined in depth and normal on mean NCC, expanded into empty image cells and
// filtered for visibility consistency and regularity, over a few rounds. TBB-parallel in waves
// committed in a fixed order, so the result does not depend on the thread count.

#include <string>
#include <vector>

#include "core/dataset/view.h"
#include "core/mvs/mvs_bounds.h"
#include "core/mvs/mvs_points.h"
#include "core/mvs/mvs_progress.h"

namespace avc::mvs {

struct PatchMvsOptions {
  // Pyramid level the views are processed at (PMVS `level`); -1 = automatic: halve until the
  // longer image side is at most 1600 px (640x480 and 1280x960 stay at 0). A coarser level is
  // several times faster but much less precise on leaves (BENCHMARKS.md, "Where the defaults
  // come from").
  int level = -1;
  // β: the image cell size in pixels at the working level; the goal is one patch per cell
  // (PMVS `csize`).
  int cell_size = 2;
  // μ: the patch is sampled on a μ x μ grid of about one reference pixel (PMVS `wsize` is 7).
  // A larger grid finds somewhat more points for much more time; 5 rather than 7 loses no
  // accuracy (BENCHMARKS.md, "Where the defaults come from").
  int window = 5;
  // α: an image belongs to V*(p) when its NCC with the reference is at least this, after and
  // before the patch is optimised (PMVS `threshold` and `threshold - 0.3`).
  double ncc_threshold = 0.7;
  double ncc_threshold_before = 0.4;
  // γ: a patch needs this many images in V*(p), the reference included (PMVS `minImageNum` 3).
  // 0 = automatic: 3, or 4 with 24 views or more, where each surface point is seen by more
  // images anyway. More images per patch: fewer false matches (precision) for less of the
  // surface covered (recall) (BENCHMARKS.md, "Where the defaults come from").
  int min_images = 0;
  // An image sees a patch only when the angle between the patch normal and the ray to the
  // camera is below this (radians, 60 deg).
  double max_view_angle = 1.05;
  // Features: the strongest η per detector (Harris, DoG) in each block x block pixel square.
  int features_per_block = 4;
  int feature_block = 32;
  // Seed matches lie within this many pixels of the epipolar line.
  double epipolar_distance = 2.0;
  // At most this many triangulated candidates are tried per feature (nearest the camera first).
  int max_seed_candidates = 24;
  // Images matched against each image for seeds (SelectNeighbours).
  int seed_neighbours = 6;
  // Expansion + filtering rounds after the seeds (PMVS: 3). Later rounds refill the cells the
  // filters emptied: each adds fewer points for more time; 1 keeps the run time under PMVS2's
  // (BENCHMARKS.md, "Where the defaults come from").
  int rounds = 1;
  // Nelder–Mead iterations for one patch, and the most images (best NCC first) it optimises
  // against; the final V*(p) is taken over all images. More of either costs CPU; the defaults
  // are the least that keep the points and their precision. The optimiser stops once the
  // simplex's costs are within 1e-3; tighter only costs time (BENCHMARKS.md, "Where the
  // defaults come from").
  int max_iterations = 20;
  int max_refine_images = 3;
  // A reference patch with a smaller RGB standard deviation (0..255) is untextured: refused.
  double min_texture = 2.0;
  // Occlusion tolerance: a patch is hidden in an image when another lies in front of it by
  // more than this many cells' footprints.
  double occlusion_cells = 2.0;
  // Regularity filter: a patch further than this many pixel footprints from the plane fitted
  // to its neighbours is dropped (PMVS `quadThreshold` 2.5). Lower is more precise on leaves
  // for a little recall, but costs a curved, textured object many of its points: PMVS's value
  // (BENCHMARKS.md, "Where the defaults come from").
  double regularity_threshold = 2.5;
  // Connected groups of patches smaller than this are dropped (filterSmallGroups).
  int min_group_size = 8;
  // Every corner of the patch's sampling grid must fall on usable (mask) pixels in every
  // image it is compared in, not just its centre: a patch straddling a thin leaf's outline
  // could match the view-dependent silhouette edge instead of the surface. 1 on, 0 off, -1
  // automatic: on when the working images' longer side is at least 1000 px (below, a leaf is too
  // few windows wide). On makes the points more precise but fewer. Off by default: the extra
  // points seed surfacer cells where there were none, which then grow over the masks, and the
  // meshes gain more than the points lose (BENCHMARKS.md, "Where the defaults come from").
  int whole_patch_in_mask = 0;
  // Patches must lie within this many proxy voxels of an occupied voxel (bounds not empty).
  int bounds_dilation = 1;

  // Empty when valid; else a sentence naming the bad field.
  std::string Validate() const;
};

// Views must be undistorted (zero distortion), with CV_8UC3 images of their camera's size and
// masks empty or CV_8UC1 of the same size with some plant pixels; at least two views. Throws
// std::invalid_argument naming the view and field at fault. Empty bounds: no proxy (depths come
// from the triangulated seeds; a seed's depth search spans the cameras' common viewing range).
// Output: oriented coloured points; `views` index `views`.
MvsPoints RunPatchMvs(const std::vector<dataset::View>& views, const MvsBounds& bounds,
                      const PatchMvsOptions& options, const MvsProgress& progress = {});

}  // namespace avc::mvs
