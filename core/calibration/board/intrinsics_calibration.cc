#include "core/calibration/board/intrinsics_calibration.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <stdexcept>
#include <utility>

#include "core/calibration/board/board_pose.h"
#include "core/calibration/board/corner_coverage.h"

namespace avc::calibration {
namespace {

struct CalibrationRun {
  camera::Intrinsics intrinsics;
  double rms_px = 0;
  std::vector<double> view_rms;
  std::vector<Eigen::Isometry3d> poses;
};

void CheckViews(const std::vector<BoardDetection>& views, const Chessboard& board) {
  if (const std::string problem = board.Validate(); !problem.empty())
    throw std::invalid_argument("intrinsics calibration: " + problem);
  if (views.empty()) throw std::invalid_argument("intrinsics calibration: no views");
  const cv::Size size = views.front().image_size;
  if (size.width <= 0 || size.height <= 0)
    throw std::invalid_argument(
        fmt::format("intrinsics calibration: view '{}' has no image size", views.front().name));
  for (const auto& view : views) {
    if (view.image_size != size)
      throw std::invalid_argument(
          fmt::format("intrinsics calibration: view '{}' is {}x{} but view '{}' is {}x{}",
                      view.name, view.image_size.width, view.image_size.height, views.front().name,
                      size.width, size.height));
    if (static_cast<int>(view.corners.size()) != board.CornerCount())
      throw std::invalid_argument(
          fmt::format("intrinsics calibration: view '{}' has {} corners, the {}x{} board has {}",
                      view.name, view.corners.size(), board.cols, board.rows, board.CornerCount()));
    for (const auto& c : view.corners) {
      if (!std::isfinite(c.x) || !std::isfinite(c.y))
        throw std::invalid_argument(
            fmt::format("intrinsics calibration: view '{}' has a non-finite corner", view.name));
    }
  }
}

struct DistortionModel {
  const char* terms;
  int flags;  // cv::calibrateCamera's: the terms left out are held at 0
};
// Simplest first.
constexpr DistortionModel kDistortionModels[] = {
    {"k1", cv::CALIB_FIX_K2 | cv::CALIB_FIX_K3 | cv::CALIB_ZERO_TANGENT_DIST},
    {"k1 k2", cv::CALIB_FIX_K3 | cv::CALIB_ZERO_TANGENT_DIST},
    {"k1 k2 p1 p2", cv::CALIB_FIX_K3},
    {"k1 k2 p1 p2 k3", 0}};
constexpr int kFullModel = 3;

CalibrationRun Calibrate(const std::vector<const BoardDetection*>& views, const Chessboard& board,
                         int flags = kDistortionModels[kFullModel].flags) {
  const std::vector<cv::Point3f> board_points = board.CornerPoints();
  std::vector<std::vector<cv::Point3f>> object_points(views.size(), board_points);
  std::vector<std::vector<cv::Point2f>> image_points;
  for (const auto* view : views) image_points.push_back(view->corners);
  const cv::Size size = views.front()->image_size;
  cv::Mat K, dist;
  std::vector<cv::Mat> rvecs, tvecs;
  cv::Mat std_intrinsics, std_extrinsics, per_view;
  CalibrationRun run;
  run.rms_px = cv::calibrateCamera(
      object_points, image_points, size, K, dist, rvecs, tvecs, std_intrinsics, std_extrinsics,
      per_view, flags,
      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-12));
  camera::Intrinsics& in = run.intrinsics;
  in.width = size.width;
  in.height = size.height;
  in.fx = K.at<double>(0, 0);
  in.fy = K.at<double>(1, 1);
  in.cx = K.at<double>(0, 2);
  in.cy = K.at<double>(1, 2);
  for (int i = 0; i < 5; ++i) in.distortion[static_cast<size_t>(i)] = dist.at<double>(i);
  if (const std::string problem = in.Validate(); !problem.empty() || !std::isfinite(run.rms_px))
    throw std::runtime_error("intrinsics calibration: OpenCV returned an unusable camera: " +
                             (problem.empty() ? std::string("non-finite RMS") : problem));
  for (size_t i = 0; i < views.size(); ++i) {
    run.view_rms.push_back(per_view.at<double>(static_cast<int>(i)));
    run.poses.push_back(PoseFromRvecTvec(rvecs[i], tvecs[i]));
  }
  return run;
}

// The board poses with `known` intrinsics: solvePnP per view, the RMS from reprojection.
CalibrationRun PosesWithKnownIntrinsics(const std::vector<const BoardDetection*>& views,
                                        const Chessboard& board, const camera::Intrinsics& known) {
  const std::vector<cv::Point3f> board_points = board.CornerPoints();
  const cv::Matx33d K(known.fx, 0, known.cx, 0, known.fy, known.cy, 0, 0, 1);
  const std::vector<double> dist(known.distortion.begin(), known.distortion.end());
  CalibrationRun run;
  run.intrinsics = known;
  double squared = 0;
  size_t corners = 0;
  for (const BoardDetection* view : views) {
    cv::Mat rvec, tvec;
    if (!cv::solvePnP(board_points, view->corners, K, dist, rvec, tvec, false,
                      cv::SOLVEPNP_ITERATIVE)) {
      throw std::runtime_error(fmt::format(
          "intrinsics calibration: no board pose for view '{}' with the given intrinsics",
          view->name));
    }
    std::vector<cv::Point2f> projected;
    cv::projectPoints(board_points, rvec, tvec, K, dist, projected);
    double view_squared = 0;
    for (size_t i = 0; i < projected.size(); ++i) {
      const cv::Point2f d = projected[i] - view->corners[i];
      view_squared += d.dot(d);
    }
    run.view_rms.push_back(std::sqrt(view_squared / static_cast<double>(projected.size())));
    run.poses.push_back(PoseFromRvecTvec(rvec, tvec));
    squared += view_squared;
    corners += projected.size();
  }
  run.rms_px = std::sqrt(squared / static_cast<double>(corners));
  return run;
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The median reprojection RMS of views held out of the model's fit (view i in fold i % folds),
// each posed with the intrinsics fitted to the other folds.
double HeldOutRms(const std::vector<const BoardDetection*>& views, const Chessboard& board,
                  const DistortionModel& model, int folds) {
  std::vector<double> rms;
  for (int fold = 0; fold < folds; ++fold) {
    std::vector<const BoardDetection*> fit, held;
    for (size_t i = 0; i < views.size(); ++i) {
      (static_cast<int>(i % static_cast<size_t>(folds)) == fold ? held : fit).push_back(views[i]);
    }
    if (held.empty()) continue;
    try {
      const CalibrationRun fitted = Calibrate(fit, board, model.flags);
      const CalibrationRun posed = PosesWithKnownIntrinsics(held, board, fitted.intrinsics);
      rms.insert(rms.end(), posed.view_rms.begin(), posed.view_rms.end());
    } catch (const std::runtime_error&) {  // a model the fold cannot fit predicts nothing
      rms.insert(rms.end(), held.size(), std::numeric_limits<double>::infinity());
    }
  }
  return Median(rms);
}

// The simplest model whose held-out RMS is within options.model_tolerance of the best's, and why.
std::pair<const DistortionModel*, std::string> ChooseDistortionModel(
    const std::vector<const BoardDetection*>& views, const Chessboard& board,
    const IntrinsicsOptions& options) {
  // Each fold must leave enough views to fit the full model.
  const int folds = std::min(options.model_folds, static_cast<int>(views.size()) / 2);
  if (folds < 2) {
    return {&kDistortionModels[1],
            fmt::format("{} views are too few to compare models: k1 k2", views.size())};
  }
  std::vector<double> scores;
  for (const DistortionModel& model : kDistortionModels) {
    scores.push_back(HeldOutRms(views, board, model, folds));
  }
  const double best = *std::min_element(scores.begin(), scores.end());
  size_t chosen = 0;
  while (scores[chosen] > best * (1 + options.model_tolerance)) ++chosen;
  std::string reason = fmt::format("held-out RMS over {} folds:", folds);
  for (size_t m = 0; m < scores.size(); ++m) {
    reason +=
        fmt::format("{} {} {:.4f} px", m == 0 ? "" : ",", kDistortionModels[m].terms, scores[m]);
  }
  return {&kDistortionModels[chosen], reason};
}

std::string DescribeRejected(const std::vector<ViewReport>& reports) {
  std::string text;
  for (const auto& r : reports) {
    if (!r.rejected) continue;
    text += fmt::format("{}'{}' ({:.2f} px)", text.empty() ? "" : ", ", r.name, r.rms_px);
  }
  return text.empty() ? "none" : text;
}

}  // namespace

IntrinsicsCalibration CalibrateIntrinsics(const std::vector<BoardDetection>& views,
                                          const Chessboard& board,
                                          const IntrinsicsOptions& options) {
  CheckViews(views, board);
  IntrinsicsOptions given = options;
  if (given.known) {
    const cv::Size size = views.front().image_size;
    if (given.known->width == 0 && given.known->height == 0) {  // a file that did not say
      given.known->width = size.width;
      given.known->height = size.height;
    }
    if (const std::string problem = given.known->Validate(); !problem.empty()) {
      throw std::invalid_argument("intrinsics calibration: the given intrinsics: " + problem);
    }
    if (given.known->width != size.width || given.known->height != size.height) {
      throw std::invalid_argument(fmt::format(
          "intrinsics calibration: the given intrinsics are for {}x{} images, the views are {}x{}",
          given.known->width, given.known->height, size.width, size.height));
    }
  }
  const int min_views = std::max(options.min_views, 3);
  if (static_cast<int>(views.size()) < min_views)
    throw std::runtime_error(fmt::format(
        "intrinsics calibration: {} views given, at least {} needed", views.size(), min_views));

  IntrinsicsCalibration result;
  result.report.views.resize(views.size());
  for (size_t i = 0; i < views.size(); ++i) result.report.views[i].name = views[i].name;
  std::vector<size_t> kept(views.size());
  for (size_t i = 0; i < views.size(); ++i) kept[i] = i;

  CalibrationRun run;
  while (true) {
    std::vector<const BoardDetection*> kept_views;
    for (size_t i : kept) kept_views.push_back(&views[i]);
    run = given.known ? PosesWithKnownIntrinsics(kept_views, board, *given.known)
                      : Calibrate(kept_views, board);
    const double median = Median(run.view_rms);
    const auto worst = std::max_element(run.view_rms.begin(), run.view_rms.end());
    const double limit = std::max(options.outlier_factor * median, options.outlier_floor_px);
    if (*worst <= limit) break;
    const size_t worst_index = static_cast<size_t>(worst - run.view_rms.begin());
    ViewReport& dropped = result.report.views[kept[worst_index]];
    dropped.rejected = true;
    dropped.rms_px = *worst;
    kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(worst_index));
    if (static_cast<int>(kept.size()) < min_views)
      throw std::runtime_error(fmt::format(
          "intrinsics calibration: only {} of {} views fit (at least {} needed); rejected: {}",
          kept.size(), views.size(), min_views, DescribeRejected(result.report.views)));
  }

  if (given.known) {
    result.report.distortion_model = "given";
  } else if (options.choose_distortion_model) {
    std::vector<const BoardDetection*> kept_pointers;
    for (size_t i : kept) kept_pointers.push_back(&views[i]);
    const auto [model, reason] = ChooseDistortionModel(kept_pointers, board, options);
    result.report.distortion_model = model->terms;
    result.report.distortion_model_reason = reason;
    if (model->flags != kDistortionModels[kFullModel].flags) {
      run = Calibrate(kept_pointers, board, model->flags);
    }
  } else {
    result.report.distortion_model = kDistortionModels[kFullModel].terms;
  }

  std::vector<BoardDetection> kept_views;
  for (size_t k = 0; k < kept.size(); ++k) {
    ViewReport& report = result.report.views[kept[k]];
    report.rms_px = run.view_rms[k];
    report.T_cam_board = run.poses[k];
    kept_views.push_back(views[kept[k]]);
  }
  result.report.rms_px = run.rms_px;
  result.report.coverage = CornerCoverage(kept_views, views.front().image_size,
                                          options.coverage_grid_cols, options.coverage_grid_rows);
  if (result.report.coverage < options.min_coverage && !given.known)
    throw std::runtime_error(fmt::format(
        "intrinsics calibration: corners cover only {:.0f}% of a {}x{} image grid (at least "
        "{:.0f}% needed): add views with the board near the image edges and corners",
        100 * result.report.coverage, options.coverage_grid_cols, options.coverage_grid_rows,
        100 * options.min_coverage));
  if (result.report.coverage < options.advised_coverage)
    result.report.warnings.push_back(
        fmt::format("corners cover {:.0f}% of the image grid; {:.0f}% or more is advised",
                    100 * result.report.coverage, 100 * options.advised_coverage));
  if (kept.size() < views.size())
    result.report.warnings.push_back("rejected views: " + DescribeRejected(result.report.views));
  result.intrinsics = run.intrinsics;
  return result;
}

}  // namespace avc::calibration
