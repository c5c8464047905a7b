#pragma once

// Synthetic chessboard photographs for calibration tests: a board seen by a known distorted
// pinhole camera, rendered by tracing every pixel centre back through the undistortion to the
// board plane and anti-aliasing each edge with a ramp one pixel wide (symmetric, so corners sit
// exactly at cv::projectPoints of the board corners).

#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/calibration/board/chessboard.h"
#include "core/camera/pinhole_camera.h"

namespace avc::calibration::testing {

// An 8-bit grey image of `board` (black/white squares, one square of white margin, grey beyond).
cv::Mat RenderBoard(const camera::Intrinsics& intrinsics, const Eigen::Isometry3d& T_cam_board,
                    const Chessboard& board);

// The test camera: 640x480, fx 600, fy 602, principal point off centre, barrel distortion with
// small tangential terms.
camera::Intrinsics TestIntrinsics();

// `count` board poses whose corners all fall inside the image with a margin, tilted up to about
// 40 degrees, spread over the image (centre region `region` = fraction of the image around
// `centre_fraction` the board centre may land in). Deterministic for a seed.
std::vector<Eigen::Isometry3d> SpreadBoardPoses(const camera::Intrinsics& intrinsics,
                                                const Chessboard& board, int count, uint64_t seed);

// Poses keeping every corner within the top-left `fraction` x `fraction` of the image.
std::vector<Eigen::Isometry3d> CornerBoardPoses(const camera::Intrinsics& intrinsics,
                                                const Chessboard& board, int count, double fraction,
                                                uint64_t seed);

}  // namespace avc::calibration::testing
