#pragma once

// How much of the image the calibration corners cover: intrinsics (above all distortion) are only
// constrained where corners were seen, so views bunched in one part of the frame extrapolate
// badly everywhere else.

#include <opencv2/core.hpp>
#include <vector>

#include "core/calibration/board/chessboard_detection.h"

namespace avc::calibration {

// Fraction of the cells of a grid_cols x grid_rows grid over an image of `image_size` that hold at
// least one corner of any view. Corners outside the image are ignored.
double CornerCoverage(const std::vector<BoardDetection>& views, cv::Size image_size,
                      int grid_cols = 8, int grid_rows = 6);

}  // namespace avc::calibration
