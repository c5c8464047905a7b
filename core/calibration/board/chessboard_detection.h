#pragma once

// Finding a chessboard's inner corners in an image with sub-pixel accuracy.

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/calibration/board/chessboard.h"

namespace avc::calibration {

// The inner corners of one view, in Chessboard::CornerPoints order (pixels, centres at integers).
struct BoardDetection {
  std::string name;  // names the view in messages (usually the image file)
  cv::Size image_size;
  std::vector<cv::Point2f> corners;
};

struct DetectionOptions {
  // cornerSubPix half window in pixels; 0 picks a third of the smallest corner spacing (clamped
  // to 2..11), which fits real images best (OpenCV's sample uses a fixed 11).
  int refine_half_window = 0;
  int refine_iterations = 100;
  double refine_epsilon = 1e-4;  // pixels
};

// Detects `board` in an 8-bit grey or BGR image: cv::findChessboardCorners, falling back to
// cv::findChessboardCornersSB when it misses, then cv::cornerSubPix on the corners, then the
// corner order fixed as Chessboard describes.
// Throws std::invalid_argument for an empty/unsupported image or bad board and
// std::runtime_error when the board is not found; both messages name `name`.
BoardDetection DetectChessboard(const cv::Mat& image, const Chessboard& board,
                                const std::string& name, const DetectionOptions& options = {});

// Reads the image at `path` (throws std::runtime_error naming it when unreadable) and detects.
BoardDetection DetectChessboardInFile(const std::filesystem::path& path, const Chessboard& board,
                                      const DetectionOptions& options = {});

}  // namespace avc::calibration
