#include "core/calibration/board/chessboard_spec.h"

#include <fmt/format.h>

namespace avc::calibration {

Eigen::Isometry3d ChessboardSpec::DefaultBoardPose(int inner_cols, int inner_rows,
                                                   double square_m) {
  // Face up: board x = world x, board y = world -y, board z = world -z.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
  pose.translation() =
      Eigen::Vector3d(-0.5 * (inner_cols - 1) * square_m, 0.5 * (inner_rows - 1) * square_m, 0);
  return pose;
}

std::string ChessboardSpec::Validate() const {
  if (inner_cols < 2 || inner_rows < 2) {
    return fmt::format("a chessboard needs at least 2 x 2 inner corners, got {} x {}", inner_cols,
                       inner_rows);
  }
  if (inner_cols == inner_rows) {
    return "a square pattern has no unique orientation; use different column and row counts";
  }
  if (!(square_m > 0 && square_m < 1)) return fmt::format("square size {} m", square_m);
  if (!(margin_squares >= 0 && margin_squares <= 10)) {
    return fmt::format("margin of {} squares", margin_squares);
  }
  if (!T_world_board.matrix().allFinite()) return "board pose is not finite";
  return "";
}

std::vector<Eigen::Vector3d> ChessboardCorners(const ChessboardSpec& spec) {
  std::vector<Eigen::Vector3d> corners;
  for (int row = 0; row < spec.inner_rows; ++row) {
    for (int col = 0; col < spec.inner_cols; ++col) {
      corners.emplace_back(col * spec.square_m, row * spec.square_m, 0);
    }
  }
  return corners;
}

}  // namespace avc::calibration
