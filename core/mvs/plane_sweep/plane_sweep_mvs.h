#pragma once

// Plane-sweep ZNCC multi-view stereo, the comparator for the patch MVS: for
// every reference view, fronto-parallel planes are swept through the plant proxy's
// per-pixel depth interval, the best-k neighbours' windowed ZNCC picks the depth per pixel
// (winner-take-all, parabola refinement), and the depth maps are filtered by geometric
// consistency and fused into oriented, coloured points.

#include <string>
#include <vector>

#include "core/dataset/view.h"
#include "core/mvs/mvs_bounds.h"
#include "core/mvs/mvs_points.h"
#include "core/mvs/mvs_progress.h"

namespace avc::mvs {

struct PlaneSweepOptions {
  // Pyramid level to work at (0 = full resolution, each level halves). -1 = automatic: the
  // smallest level whose longer image side is at most 800 px (level 0 for 640x480, level 1 for
  // 1280x960): the patch MVS's rule, so the two are compared on the same pixels.
  int level = -1;
  // ZNCC window side in pixels at the working level (odd, >= 3). Wider matches weak texture more
  // reliably, but a fronto-parallel window fattens thin leaves and object edges: 5 rather than
  // PMVS's 7, for precision (BENCHMARKS.md, "Where the defaults come from").
  int window = 5;
  int neighbours = 4;  // views swept against each reference: SelectNeighbours' best first
  int best_k = 2;      // per pixel and plane: mean ZNCC of the best k neighbours
  // Planes are uniform in inverse depth, spaced so that moving to the next plane shifts the
  // projection in any neighbour by at most this many pixels; at most max_planes per reference.
  double max_plane_step_px = 1.0;
  int max_planes = 768;
  // The proxy's per-pixel depth interval is widened by this many voxel sizes on each side.
  double depth_margin_voxels = 1.0;
  // Windows whose grey standard deviation (0..1 scale) is below this carry no texture.
  double min_texture_std = 0.008;
  double min_score = 0.6;  // aggregated ZNCC a depth needs to be kept
  // A depth is consistent with another view's depth map when they agree within this fraction
  // of the depth; a pixel needs min_consistent_views such views to become a point.
  double consistency_tolerance = 0.004;
  int min_consistent_views = 2;
  // Fusion keeps the most confident point per cubic cell of this many pixel footprints (the
  // median depth over the median focal length at the working level), PMVS's csize 2 analogue.
  double cell_px = 2.0;
  int normal_step_px = 2;  // depth-map normals from back-projected points this far apart

  // Empty when valid; else a sentence naming the bad field.
  std::string Validate() const;
};

// Views: undistorted (distortion zero), at least two, images CV_8UC3 BGR of the camera's size,
// masks empty (= reconstruct everywhere) or CV_8UC1 of the image size with some plant pixels.
// Bounds: the plant proxy; when empty the search is limited to the largest sphere around the
// point the cameras look at (NearestPointToAxes) that every camera sees whole. Output points'
// views index `views`; same inputs → bitwise-identical output, whatever the thread count.
// Throws std::invalid_argument naming the view and field at fault.
MvsPoints RunPlaneSweep(const std::vector<dataset::View>& views, const MvsBounds& bounds,
                        const PlaneSweepOptions& options = {}, const MvsProgress& progress = {});

}  // namespace avc::mvs
