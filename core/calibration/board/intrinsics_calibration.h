#pragma once

// Camera intrinsics (fx fy cx cy, k1 k2 p1 p2 k3) from chessboard views with cv::calibrateCamera,
// rejecting views that do not fit and refusing sets that cannot constrain the model.
//
// With choose_distortion_model the distortion model is chosen by the data: k1; k1 k2; k1 k2 p1
// p2; or k1 k2 p1 p2 k3, each scored by the reprojection RMS of views held out of its fit
// (5-fold, median); the best score wins (the simplest on a tie), so terms that only fit the
// noise of a few views (a k3 of several units from 8 views) lose to the model that predicts new
// views. It is not the default: held-out views look like the fitted ones, so they cannot show
// what a dropped term does where no view reached, and on rendered views of a distorted camera the
// chosen model lands rays further off at the image edges than the full model (BENCHMARKS.md,
// "Where the defaults come from"). The report names the model (and the scores when chosen).
//
// Known intrinsics (IntrinsicsOptions::known, e.g. the maker's or an earlier calibration from
// many views) are kept as they are: each view's board pose is then solved with them alone
// (cv::solvePnP), and the same rejection rule and report apply. Few views of one board cannot
// constrain five distortion terms; known intrinsics avoid fitting them.
//
// View rejection rule: calibrate, take the per-view reprojection RMS; while the worst view's RMS
// exceeds both `outlier_factor` x the median view RMS and `outlier_floor_px`, drop that one view
// and recalibrate (one at a time, since a single bad view inflates every other view's RMS).

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/calibration/board/chessboard.h"
#include "core/calibration/board/chessboard_detection.h"
#include "core/camera/pinhole_camera.h"

namespace avc::calibration {

struct IntrinsicsOptions {
  int min_views = 5;              // refuse with fewer usable views
  double outlier_factor = 3.0;    // reject a view above this multiple of the median view RMS ...
  double outlier_floor_px = 0.3;  // ... and above this absolute RMS (noise-free sets stay whole)
  int coverage_grid_cols = 8;
  int coverage_grid_rows = 6;
  double min_coverage = 0.4;       // refuse below this fraction of grid cells with corners
  double advised_coverage = 0.75;  // warn below this fraction
  // Set: these intrinsics are used, not estimated (the coverage then only warns). Their size
  // must be the images'.
  std::optional<camera::Intrinsics> known;
  // False: k1 k2 p1 p2 k3 (OpenCV's default model).
  bool choose_distortion_model = false;
  // A simpler model is kept while its held-out RMS is within this fraction of the best's. 0: the
  // best. Higher prefers fewer terms; but views near the centre cannot show what the outer terms
  // do at the edges, so a model that scores nearly as well can still move the principal point
  // and the cameras: 0 (BENCHMARKS.md, "Where the defaults come from").
  double model_tolerance = 0;
  int model_folds = 5;
};

struct ViewReport {
  std::string name;
  double rms_px = 0;  // reprojection RMS at the final (or rejecting) calibration
  bool rejected = false;
  Eigen::Isometry3d T_cam_board = Eigen::Isometry3d::Identity();  // valid for kept views
};

struct IntrinsicsReport {
  double rms_px = 0;              // overall RMS over the kept views
  double coverage = 0;            // fraction of the coverage grid with corners (kept views)
  std::vector<ViewReport> views;  // in input order
  std::vector<std::string> warnings;
  std::string distortion_model;         // the terms estimated, e.g. "k1 k2"; "given" for known ones
  std::string distortion_model_reason;  // the held-out RMS of every model tried
};

struct IntrinsicsCalibration {
  camera::Intrinsics intrinsics;
  IntrinsicsReport report;
};

// Throws std::invalid_argument for a bad board, views of different image sizes or with a wrong
// corner count / non-finite corners (naming the view), and std::runtime_error when fewer than
// min_views remain (naming the rejected views and their RMS), when coverage is below
// min_coverage, or when OpenCV fails or returns non-finite values.
IntrinsicsCalibration CalibrateIntrinsics(const std::vector<BoardDetection>& views,
                                          const Chessboard& board,
                                          const IntrinsicsOptions& options = {});

}  // namespace avc::calibration
