#include "core/calibration/board/chessboard.h"

#include <fmt/format.h>

#include <cmath>

namespace avc::calibration {

std::string Chessboard::Validate() const {
  if (cols < 2 || rows < 2)
    return fmt::format("chessboard needs at least 2x2 inner corners, got {}x{}", cols, rows);
  // A square board has no defined orientation: detections could come back rotated by 90 degrees.
  if (cols == rows) return fmt::format("chessboard {}x{} is square; use cols != rows", cols, rows);
  if (!std::isfinite(square_size) || !(square_size > 0))
    return fmt::format("chessboard square size {} m must be positive", square_size);
  return {};
}

std::vector<cv::Point3f> Chessboard::CornerPoints() const {
  std::vector<cv::Point3f> points;
  points.reserve(static_cast<size_t>(CornerCount()));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      points.emplace_back(static_cast<float>(c * square_size), static_cast<float>(r * square_size),
                          0.f);
    }
  }
  return points;
}

}  // namespace avc::calibration
