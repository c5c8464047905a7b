// Real-data check on OpenCV's sample chessboard set (13 left views, 9x6, 25 mm) against the
// reference left_intrinsics.yml that OpenCV's calibration sample produced from them.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <opencv2/core.hpp>
#include <optional>
#include <stdexcept>

#include "core/calibration/board/board_pose.h"
#include "core/calibration/board/chessboard_detection.h"
#include "core/calibration/board/intrinsics_calibration.h"
#include "tests/support/test_support.h"

namespace avc::calibration {
namespace {

std::filesystem::path SharedData() { return avc::testing::SharedDataDir(); }

struct RealRun {
  IntrinsicsCalibration result;
  double dfx = 0, dfy = 0, dcx = 0, dcy = 0;  // minus the reference, pixels
};

// Detects the 13 left views with `options`, calibrates, and compares with left_intrinsics.yml.
// Empty when the shared data is absent.
std::optional<RealRun> CalibrateLeftViews(const DetectionOptions& options,
                                          const IntrinsicsOptions& calibration, const char* label) {
  const std::filesystem::path folder = SharedData() / "chessboard_opencv";
  if (!std::filesystem::exists(folder / "left_intrinsics.yml")) return std::nullopt;
  cv::FileStorage reference((folder / "left_intrinsics.yml").string(), cv::FileStorage::READ);
  cv::Mat K_ref;
  reference["camera_matrix"] >> K_ref;
  if (K_ref.rows != 3 || K_ref.cols != 3)
    throw std::runtime_error("left_intrinsics.yml has no 3x3 camera_matrix");

  std::vector<std::filesystem::path> images;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("left", 0) == 0 && entry.path().extension() == ".jpg")
      images.push_back(entry.path());
  }
  std::sort(images.begin(), images.end());
  if (images.size() != 13) throw std::runtime_error("expected 13 left*.jpg images");
  const Chessboard board{9, 6, 0.025};
  std::vector<BoardDetection> views;
  for (const auto& path : images) views.push_back(DetectChessboardInFile(path, board, options));

  RealRun run{CalibrateIntrinsics(views, board, calibration)};
  const camera::Intrinsics& in = run.result.intrinsics;
  run.dfx = in.fx - K_ref.at<double>(0, 0);
  run.dfy = in.fy - K_ref.at<double>(1, 1);
  run.dcx = in.cx - K_ref.at<double>(0, 2);
  run.dcy = in.cy - K_ref.at<double>(1, 2);
  std::cout << label << ": fx " << in.fx << " fy " << in.fy << " cx " << in.cx << " cy " << in.cy
            << "; minus reference: " << run.dfx << " " << run.dfy << " " << run.dcx << " "
            << run.dcy << " px; rms " << run.result.report.rms_px << " px, coverage "
            << run.result.report.coverage << "\n";
  for (const auto& view : run.result.report.views)
    std::cout << "  " << std::filesystem::path(view.name).filename().string() << " rms "
              << view.rms_px << (view.rejected ? " REJECTED" : "") << "\n";
  return run;
}

// The reference was made by OpenCV's calibration sample, which refines corners with a fixed
// 11-pixel half window and 30 iterations and keeps every view. With the same refinement and no
// view rejection our pipeline must reproduce it to 0.5 px.
TEST(RealChessboard, ReproducesOpenCvReferenceWithItsSettings) {
  DetectionOptions sample_refinement;
  sample_refinement.refine_half_window = 11;
  sample_refinement.refine_iterations = 30;
  IntrinsicsOptions keep_all;
  keep_all.outlier_factor = 1e9;
  const auto run =
      CalibrateLeftViews(sample_refinement, keep_all, "sample settings (11 px, 30 it, keep all)");
  if (!run) GTEST_SKIP() << "shared data not found under " << SharedData();
  EXPECT_LT(std::abs(run->dfx), 0.5);
  EXPECT_LT(std::abs(run->dfy), 0.5);
  EXPECT_LT(std::abs(run->dcx), 0.5);
  EXPECT_LT(std::abs(run->dcy), 0.5);
  EXPECT_NEAR(run->result.report.rms_px, 0.41, 0.03);
}

// Under the sample's refinement left02 fits six times worse than the median view (the reference
// file lists it at 1.18 px); the rejection rule drops exactly that view.
TEST(RealChessboard, RejectionDropsTheViewTheSampleRefinementSpoils) {
  DetectionOptions sample_refinement;
  sample_refinement.refine_half_window = 11;
  sample_refinement.refine_iterations = 30;
  const auto run = CalibrateLeftViews(sample_refinement, {}, "sample refinement, rejection on");
  if (!run) GTEST_SKIP() << "shared data not found under " << SharedData();
  for (const auto& view : run->result.report.views) {
    const bool is_left02 = view.name.find("left02.jpg") != std::string::npos;
    EXPECT_EQ(view.rejected, is_left02) << view.name;
  }
  EXPECT_LT(run->result.report.rms_px, 0.25);
}

// Our default refinement window (a third of the corner spacing) fits the same images with less
// than half the reprojection error of the sample's; its intrinsics differ from the reference by
// about 3 px in focal length, within what the corner refinement alone moves them.
TEST(RealChessboard, DefaultRefinementFitsTheImagesBetter) {
  const auto run = CalibrateLeftViews({}, {}, "default settings");
  if (!run) GTEST_SKIP() << "shared data not found under " << SharedData();
  EXPECT_LT(run->result.report.rms_px, 0.2);
  EXPECT_LT(std::abs(run->dfx), 4.0);
  EXPECT_LT(std::abs(run->dfy), 4.0);
  EXPECT_LT(std::abs(run->dcx), 1.0);
  EXPECT_LT(std::abs(run->dcy), 2.0);
  for (const auto& view : run->result.report.views) EXPECT_FALSE(view.rejected) << view.name;
}

// Which intrinsics are closer to the truth, with no truth at hand: leave one view out, calibrate
// on the other twelve, and measure how well the result predicts the held-out view's corners
// (found either way). The default's intrinsics predict held-out views better on both corner sets
// (measured: 0.182 vs 0.197 px on default corners, 0.302 vs 0.311 px on the sample's), so the 3 px
// gap to left_intrinsics.yml is the reference's large refinement window, not an error of ours.
TEST(RealChessboard, DefaultIntrinsicsPredictHeldOutViewsBetterThanTheReferenceSettings) {
  const std::filesystem::path folder = SharedData() / "chessboard_opencv";
  if (!std::filesystem::exists(folder / "left_intrinsics.yml")) {
    GTEST_SKIP() << "shared data not found under " << SharedData();
  }
  std::vector<std::filesystem::path> images;
  for (int i = 1; i <= 14; ++i) {
    const auto path = folder / fmt::format("left{:02d}.jpg", i);
    if (std::filesystem::exists(path)) images.push_back(path);
  }
  ASSERT_EQ(images.size(), 13u);
  const Chessboard board{9, 6, 0.025};
  DetectionOptions sample_refinement;
  sample_refinement.refine_half_window = 11;
  sample_refinement.refine_iterations = 30;
  std::vector<BoardDetection> ours, sample;
  for (const auto& path : images) {
    ours.push_back(DetectChessboardInFile(path, board, {}));
    sample.push_back(DetectChessboardInFile(path, board, sample_refinement));
  }
  IntrinsicsOptions keep_all;
  keep_all.outlier_factor = 1e9;
  keep_all.min_coverage = 0;
  // Mean held-out RMS on [our corners, the sample's corners] for intrinsics trained on `train`.
  const auto held_out = [&](const std::vector<BoardDetection>& train) {
    std::array<double, 2> sum{0, 0};
    for (size_t out = 0; out < images.size(); ++out) {
      std::vector<BoardDetection> rest;
      for (size_t i = 0; i < images.size(); ++i) {
        if (i != out) rest.push_back(train[i]);
      }
      const camera::Intrinsics k = CalibrateIntrinsics(rest, board, keep_all).intrinsics;
      sum[0] += EstimateBoardPose(board.CornerPoints(), ours[out].corners, k, "ours").rms_px;
      sum[1] += EstimateBoardPose(board.CornerPoints(), sample[out].corners, k, "sample").rms_px;
    }
    return std::array<double, 2>{sum[0] / images.size(), sum[1] / images.size()};
  };
  const std::array<double, 2> default_trained = held_out(ours);
  const std::array<double, 2> sample_trained = held_out(sample);
  std::cout << "held-out RMS, default-trained: " << default_trained[0] << " / "
            << default_trained[1] << " px; sample-trained: " << sample_trained[0] << " / "
            << sample_trained[1] << " px\n";
  EXPECT_LT(default_trained[0], sample_trained[0]);
  EXPECT_LT(default_trained[1], sample_trained[1]);
}

}  // namespace
}  // namespace avc::calibration
