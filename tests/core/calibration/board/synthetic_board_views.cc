#include "tests/core/calibration/board/synthetic_board_views.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace avc::calibration::testing {
namespace {

// Uniform in [lo, hi) from raw generator bits (identical across standard libraries).
double Uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// Fraction of a pixel inside the slab lo <= x < hi along one board axis: a linear ramp one pixel
// wide across each edge (`scale` = board metres per pixel across the edge). Symmetric about the
// edge, so edges and corners land exactly where the projection puts them.
double SlabCoverage(double x, double lo, double hi, double scale) {
  const double inside = std::min(x - lo, hi - x) / scale;
  return std::clamp(inside + 0.5, 0.0, 1.0);
}

// Anti-aliased square wave +-1 with period 2s, +1 on [0, s): (-1)^floor(x / s).
double SquareWave(double x, double s, double scale) {
  const double k = std::round(x / s);
  const double t = (x - k * s) / scale;  // signed pixel distance to the nearest edge
  const double sign = (static_cast<long>(k) % 2 == 0) ? 1.0 : -1.0;
  return sign * std::clamp(2 * t, -1.0, 1.0);
}

constexpr double kBlack = 20, kWhite = 235, kBackground = 90;

// Grey level at board point (x, y) seen by a pixel spanning (scale_x, scale_y) board metres.
double BoardShade(const Chessboard& board, double x, double y, double scale_x, double scale_y) {
  const double s = board.square_size;
  const double squares =
      SlabCoverage(x, -s, board.cols * s, scale_x) * SlabCoverage(y, -s, board.rows * s, scale_y);
  const double paper = SlabCoverage(x, -2 * s, (board.cols + 1) * s, scale_x) *
                       SlabCoverage(y, -2 * s, (board.rows + 1) * s, scale_y);
  // Black where floor(x/s) + floor(y/s) is even, i.e. where the two waves agree.
  const double checker = 0.5 * (kBlack + kWhite) - 0.5 * (kWhite - kBlack) *
                                                       SquareWave(x, s, scale_x) *
                                                       SquareWave(y, s, scale_y);
  const double on_paper = squares * checker + (1 - squares) * kWhite;
  return paper * on_paper + (1 - paper) * kBackground;
}

bool CornersInside(const camera::Intrinsics& intrinsics, const Chessboard& board,
                   const Eigen::Isometry3d& T_cam_board, double u_max, double v_max,
                   double margin) {
  // All squares must be visible; the white margin may run off the image.
  const double s = board.square_size;
  const double xs[] = {-s, board.cols * s};
  const double ys[] = {-s, board.rows * s};
  for (double x : xs) {
    for (double y : ys) {
      const auto pixel = intrinsics.Project(T_cam_board * Eigen::Vector3d(x, y, 0));
      if (!pixel || pixel->x() < margin || pixel->y() < margin || pixel->x() > u_max - margin ||
          pixel->y() > v_max - margin)
        return false;
    }
  }
  return true;
}

Eigen::Isometry3d RandomPose(std::mt19937_64& rng, const camera::Intrinsics& intrinsics,
                             const Chessboard& board, double u_max, double v_max, double z_lo,
                             double z_hi) {
  const double tilt = 40 * M_PI / 180;
  // One draw per statement, last factor first: the order GCC evaluated them in one expression
  // (clang evaluates the other way), so the views stay the ones the tests were written with.
  const double spin = Uniform(rng, -0.3, 0.3);
  const double tilt_y = Uniform(rng, -tilt, tilt);
  const double tilt_x = Uniform(rng, -tilt, tilt);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(tilt_x, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(tilt_y, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(spin, Eigen::Vector3d::UnitZ()))
                                .toRotationMatrix();
  const double v = Uniform(rng, 0, v_max);
  const Eigen::Vector2d pixel(Uniform(rng, 0, u_max), v);
  const Eigen::Vector3d ray = intrinsics.Ray(pixel);
  const double depth = Uniform(rng, z_lo, z_hi);
  const Eigen::Vector3d centre_board((board.cols - 1) * board.square_size / 2,
                                     (board.rows - 1) * board.square_size / 2, 0);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = ray / ray.z() * depth - R * centre_board;
  return T;
}

std::vector<Eigen::Isometry3d> SamplePoses(const camera::Intrinsics& intrinsics,
                                           const Chessboard& board, int count, double u_max,
                                           double v_max, double z_lo, double z_hi, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Eigen::Isometry3d> poses;
  for (int attempt = 0; attempt < 200000 && static_cast<int>(poses.size()) < count; ++attempt) {
    const Eigen::Isometry3d T = RandomPose(rng, intrinsics, board, u_max, v_max, z_lo, z_hi);
    if (CornersInside(intrinsics, board, T, u_max, v_max, 4)) poses.push_back(T);
  }
  if (static_cast<int>(poses.size()) < count)
    throw std::runtime_error("could not place enough synthetic board views");
  return poses;
}

}  // namespace

camera::Intrinsics TestIntrinsics() {
  camera::Intrinsics in;
  in.width = 640;
  in.height = 480;
  in.fx = 600;
  in.fy = 602;
  in.cx = 324.5;
  in.cy = 236.25;
  in.distortion = {-0.15, 0.08, 0.0012, -0.0008, -0.02};
  return in;
}

cv::Mat RenderBoard(const camera::Intrinsics& intrinsics, const Eigen::Isometry3d& T_cam_board,
                    const Chessboard& board) {
  // Pixel ray d = (x, y, 1) meets the board plane where H * (X, Y, 1) ~ d, H = [r1 r2 t].
  Eigen::Matrix3d H;
  H << T_cam_board.linear().col(0), T_cam_board.linear().col(1), T_cam_board.translation();
  const Eigen::Matrix3d H_inv = H.inverse();
  const int w = intrinsics.width, h = intrinsics.height;
  // Board coordinates of every pixel centre, one extra row and column for the pixel footprint.
  std::vector<Eigen::Vector2d> on_board(static_cast<size_t>((w + 1) * (h + 1)));
  std::vector<char> visible(on_board.size());
  for (int v = 0; v <= h; ++v) {
    for (int u = 0; u <= w; ++u) {
      const Eigen::Vector2d n = intrinsics.Undistort(
          {(u - intrinsics.cx) / intrinsics.fx, (v - intrinsics.cy) / intrinsics.fy});
      const Eigen::Vector3d b = H_inv * Eigen::Vector3d(n.x(), n.y(), 1);
      const size_t i = static_cast<size_t>(v * (w + 1) + u);
      visible[i] = b.z() > 0;
      on_board[i] = b.head<2>() / b.z();
    }
  }
  cv::Mat image(h, w, CV_8U);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      const size_t i = static_cast<size_t>(v * (w + 1) + u);
      const size_t right = i + 1, below = i + static_cast<size_t>(w + 1);
      double shade = kBackground;
      if (visible[i] && visible[right] && visible[below]) {
        const Eigen::Vector2d du = on_board[right] - on_board[i];
        const Eigen::Vector2d dv = on_board[below] - on_board[i];
        // Board metres per pixel across a line x = const: |grad x| over the pixel grid.
        const double scale_x = Eigen::Vector2d(du.x(), dv.x()).norm();
        const double scale_y = Eigen::Vector2d(du.y(), dv.y()).norm();
        shade = BoardShade(board, on_board[i].x(), on_board[i].y(), std::max(scale_x, 1e-12),
                           std::max(scale_y, 1e-12));
      }
      image.at<uint8_t>(v, u) = static_cast<uint8_t>(std::lround(shade));
    }
  }
  return image;
}

std::vector<Eigen::Isometry3d> SpreadBoardPoses(const camera::Intrinsics& intrinsics,
                                                const Chessboard& board, int count, uint64_t seed) {
  return SamplePoses(intrinsics, board, count, intrinsics.width, intrinsics.height, 0.25, 0.6,
                     seed);
}

std::vector<Eigen::Isometry3d> CornerBoardPoses(const camera::Intrinsics& intrinsics,
                                                const Chessboard& board, int count, double fraction,
                                                uint64_t seed) {
  return SamplePoses(intrinsics, board, count, intrinsics.width * fraction,
                     intrinsics.height * fraction, 0.7, 1.0, seed);
}

}  // namespace avc::calibration::testing
