#pragma once

// An automatic box around the object for the plant proxy, with no hand-set bounding box.
//
// Assumption: every camera looks at the object, which lies near its image centre (as the cell's
// first pass arranges, paper Algorithm 1 line 4). The point nearest (least squares) to all optical
// axes is taken as the object's centre, and a cube around it sized by the widest field of view at
// that distance as the first guess; a coarse carving pass with the masks then shrinks the box to
// the occupied voxels plus a margin, growing it first where the object touches its sides.

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/dataset/view.h"

namespace avc::ppr {

struct BoundsOptions {
  int coarse_cells = 64;  // voxels along the longest edge of the coarse pass
  int margin_cells = 2;   // coarse voxels added on every side of the carved survivors
  int background_votes_allowed = 1;
  int min_plant_views = 0;   // 0 = automatic, as ProxyOptions
  int max_growth_steps = 3;  // times the box may grow where survivors touch its faces
};

// The first guess from cameras only. Throws std::invalid_argument with fewer than two cameras,
// parallel optical axes, a bad camera, or a centre behind a camera.
Eigen::AlignedBox3d BoxFromCameras(const std::vector<camera::Camera>& cameras);

// The box after the coarse carving pass. masks[i] belongs to cameras[i] (CV_8UC1, non-zero =
// plant). Throws std::invalid_argument for no views, a size mismatch or bad input (naming the
// view), std::runtime_error when no voxel survives carving.
Eigen::AlignedBox3d BoundsFromViews(const std::vector<camera::Camera>& cameras,
                                    const std::vector<cv::Mat>& masks,
                                    const BoundsOptions& options = {});
Eigen::AlignedBox3d BoundsFromViews(const std::vector<dataset::View>& views,
                                    const BoundsOptions& options = {});

}  // namespace avc::ppr
