#include "core/calibration/board/chessboard_detection.h"

#include <fmt/format.h>

#include <algorithm>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::calibration {
namespace {

cv::Mat ToGrey(const cv::Mat& image, const std::string& name) {
  if (image.empty()) throw std::invalid_argument(fmt::format("image '{}' is empty", name));
  if (image.depth() != CV_8U)
    throw std::invalid_argument(
        fmt::format("image '{}' is not 8-bit (depth {})", name, image.depth()));
  if (image.channels() == 1) return image;
  cv::Mat grey;
  if (image.channels() == 3) {
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  } else if (image.channels() == 4) {
    cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  } else {
    throw std::invalid_argument(
        fmt::format("image '{}' has {} channels; expected 1, 3 or 4", name, image.channels()));
  }
  return grey;
}

// A half window of a third of the smallest corner spacing (along rows and columns) refines
// without reaching the neighbouring corners.
int RefinementHalfWindow(const std::vector<cv::Point2f>& corners, const Chessboard& board) {
  const auto at = [&](int c, int r) { return corners[static_cast<size_t>(r * board.cols + c)]; };
  double spacing = 1e9;
  for (int r = 0; r < board.rows; ++r) {
    for (int c = 0; c < board.cols; ++c) {
      if (c + 1 < board.cols)
        spacing = std::min(spacing, static_cast<double>(cv::norm(at(c + 1, r) - at(c, r))));
      if (r + 1 < board.rows)
        spacing = std::min(spacing, static_cast<double>(cv::norm(at(c, r + 1) - at(c, r))));
    }
  }
  return std::clamp(static_cast<int>(spacing / 3), 2, 11);
}

// Mean grey level at the centre of the square between inner corners (col, row) and
// (col + 1, row + 1).
double SquareShade(const cv::Mat& grey, const std::vector<cv::Point2f>& corners,
                   const Chessboard& board, int col, int row) {
  const auto at = [&](int c, int r) { return corners[static_cast<size_t>(r * board.cols + c)]; };
  const cv::Point2f centre =
      0.25f * (at(col, row) + at(col + 1, row) + at(col, row + 1) + at(col + 1, row + 1));
  cv::Mat patch;
  cv::getRectSubPix(grey, cv::Size(3, 3), centre, patch, CV_32F);
  return cv::mean(patch)[0];
}

// Detectors may return the corners starting from either end of the board (a half turn). When
// cols + rows is odd the two ends differ in colour, so fix the order: the square inside the first
// corner is dark. Symmetric boards keep the detector's order.
void CanonicalizeCornerOrder(const cv::Mat& grey, const Chessboard& board,
                             std::vector<cv::Point2f>& corners) {
  if ((board.cols + board.rows) % 2 == 0) return;
  const double first = SquareShade(grey, corners, board, 0, 0);
  const double last = SquareShade(grey, corners, board, board.cols - 2, board.rows - 2);
  if (first > last) std::reverse(corners.begin(), corners.end());
}

}  // namespace

BoardDetection DetectChessboard(const cv::Mat& image, const Chessboard& board,
                                const std::string& name, const DetectionOptions& options) {
  if (const std::string problem = board.Validate(); !problem.empty())
    throw std::invalid_argument(fmt::format("detecting in '{}': {}", name, problem));
  const cv::Mat grey = ToGrey(image, name);
  BoardDetection detection{name, grey.size(), {}};
  // The classic detector plus cornerSubPix is the more accurate pair on sharp images (the SB
  // detector's own sub-pixel corners were up to 0.35 px off on rendered boards and moved the
  // OpenCV sample calibration by 4 px in fx); SB finds boards the classic one misses (blur,
  // strong perspective), and its corners are refined the same way.
  bool found =
      cv::findChessboardCorners(grey, board.PatternSize(), detection.corners,
                                cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE);
  if (!found) {
    found = cv::findChessboardCornersSB(grey, board.PatternSize(), detection.corners,
                                        cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_EXHAUSTIVE);
  }
  if (!found || static_cast<int>(detection.corners.size()) != board.CornerCount()) {
    throw std::runtime_error(fmt::format("chessboard {}x{} not found in image '{}' ({}x{})",
                                         board.cols, board.rows, name, grey.cols, grey.rows));
  }
  const int half_window = options.refine_half_window > 0
                              ? options.refine_half_window
                              : RefinementHalfWindow(detection.corners, board);
  cv::cornerSubPix(grey, detection.corners, cv::Size(half_window, half_window), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT,
                                    options.refine_iterations, options.refine_epsilon));
  CanonicalizeCornerOrder(grey, board, detection.corners);
  return detection;
}

BoardDetection DetectChessboardInFile(const std::filesystem::path& path, const Chessboard& board,
                                      const DetectionOptions& options) {
  const cv::Mat image = cv::imread(path.string(), cv::IMREAD_GRAYSCALE);
  if (image.empty()) throw std::runtime_error(fmt::format("cannot read image '{}'", path.string()));
  return DetectChessboard(image, board, path.string(), options);
}

}  // namespace avc::calibration
