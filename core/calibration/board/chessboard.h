#pragma once

// A planar chessboard target: its inner-corner grid and square size, and where each inner corner
// lies in the board frame (origin at the first inner corner, x along a row of `cols` corners, y
// along a column, z = x cross y, into the board seen from the front; metres). When cols + rows is
// odd the origin is the end corner whose adjacent squares are dark (detection enforces it), so
// poses are unambiguous; boards with cols + rows even are symmetric under a half turn.

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace avc::calibration {

struct Chessboard {
  int cols = 9;                // inner corners per row
  int rows = 6;                // inner corners per column
  double square_size = 0.025;  // metres

  int CornerCount() const { return cols * rows; }
  cv::Size PatternSize() const { return {cols, rows}; }
  // Empty when usable, else a sentence naming the bad field.
  std::string Validate() const;
  // Board-frame coordinates of the inner corners in OpenCV's detection order (row by row).
  std::vector<cv::Point3f> CornerPoints() const;
};

}  // namespace avc::calibration
