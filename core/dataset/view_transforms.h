#pragma once

// Changes to views that the reconstruction makes before it starts: removing lens distortion
// (so that MVS and carving can use the plain pinhole P = K[R|t]) and pyramid levels (PMVS's
// `level`: level 1 halves the resolution).

#include "core/dataset/view.h"

namespace avc::dataset {

// Resamples image and mask so that the camera has no distortion (same K, same size); a view
// without distortion is left untouched.
void Undistort(View& view);

// The view at pyramid level `level` (0 = unchanged): each level halves width and height
// (cv::pyrDown for the image, nearest for the mask) and scales the intrinsics to match, with
// pixel centres at integer coordinates. Throws std::invalid_argument when the image would
// become smaller than 16 pixels.
View AtPyramidLevel(const View& view, int level);

}  // namespace avc::dataset
