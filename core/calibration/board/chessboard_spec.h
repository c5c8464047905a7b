#pragma once

// A printed chessboard lying on the turntable, as the calibration plans for it and the simulator
// draws it. Its board frame follows OpenCV's object points: origin at the first inner corner, x
// along the pattern's columns, y along its rows, z = 0 on the board and z pointing INTO the table
// (away from every camera that sees it, as OpenCV's detector orders corners). The board lies in
// the world's xy plane, so calibration views look at it from above.

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace avc::calibration {

struct ChessboardSpec {
  int inner_cols = 9;         // inner corners per row (OpenCV pattern width)
  int inner_rows = 6;         // inner corners per column (pattern height)
  double square_m = 0.025;    // side of one square
  double margin_squares = 1;  // white border around the squares, in squares
  // Board frame in the world frame. Default: the squares centred on the turntable axis, lying
  // on the table top face up (board z = world -z; the first inner corner then sits about
  // 0.12 m off the axis).
  Eigen::Isometry3d T_world_board = DefaultBoardPose(9, 6, 0.025);

  static Eigen::Isometry3d DefaultBoardPose(int inner_cols, int inner_rows, double square_m);
  // Empty when usable, else the bad field.
  std::string Validate() const;
};

// The inner corners in the board frame, row by row (OpenCV's order for the pattern size
// inner_cols x inner_rows).
std::vector<Eigen::Vector3d> ChessboardCorners(const ChessboardSpec& spec);

}  // namespace avc::calibration
