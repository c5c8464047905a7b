#include "core/calibration/board/corner_coverage.h"

#include <stdexcept>

namespace avc::calibration {

double CornerCoverage(const std::vector<BoardDetection>& views, cv::Size image_size, int grid_cols,
                      int grid_rows) {
  if (image_size.width <= 0 || image_size.height <= 0 || grid_cols <= 0 || grid_rows <= 0)
    throw std::invalid_argument("corner coverage needs a positive image size and grid");
  std::vector<char> covered(static_cast<size_t>(grid_cols * grid_rows), 0);
  for (const auto& view : views) {
    for (const auto& corner : view.corners) {
      // Pixel centres are at integers, so the image spans [-0.5, size - 0.5).
      const double u = (corner.x + 0.5) / image_size.width;
      const double v = (corner.y + 0.5) / image_size.height;
      if (!(u >= 0 && u < 1 && v >= 0 && v < 1)) continue;
      const int col = static_cast<int>(u * grid_cols);
      const int row = static_cast<int>(v * grid_rows);
      covered[static_cast<size_t>(row * grid_cols + col)] = 1;
    }
  }
  int count = 0;
  for (char c : covered) count += c;
  return static_cast<double>(count) / static_cast<double>(covered.size());
}

}  // namespace avc::calibration
