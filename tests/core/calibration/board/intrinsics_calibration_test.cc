// Intrinsics from synthetic chessboard photographs rendered with a known camera: recovery,
// rejection of a corrupted view, the coverage refusal and named errors for bad input.

#include "core/calibration/board/intrinsics_calibration.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <stdexcept>

#include "core/calibration/board/board_pose.h"
#include "core/calibration/board/chessboard_detection.h"
#include "tests/core/calibration/board/synthetic_board_views.h"

namespace avc::calibration {
namespace {

using testing::CornerBoardPoses;
using testing::RenderBoard;
using testing::SpreadBoardPoses;
using testing::TestIntrinsics;

struct SyntheticSet {
  std::vector<BoardDetection> views;
  std::vector<Eigen::Isometry3d> poses;
};

SyntheticSet DetectRendered(const std::vector<Eigen::Isometry3d>& poses, const Chessboard& board) {
  SyntheticSet set;
  set.poses = poses;
  for (size_t i = 0; i < poses.size(); ++i) {
    const cv::Mat image = RenderBoard(TestIntrinsics(), poses[i], board);
    set.views.push_back(DetectChessboard(image, board, "synthetic_" + std::to_string(i)));
  }
  return set;
}

// A 9x6 board of 20 mm squares: small enough to reach into the image corners.
const Chessboard kBoard{9, 6, 0.02};

// Rendering and detection take a second or two; share one set between the tests.
const SyntheticSet& SpreadSet() {
  static const SyntheticSet set =
      DetectRendered(SpreadBoardPoses(TestIntrinsics(), kBoard, 20, 7), kBoard);
  return set;
}

// k2 and k3 trade off against each other over the image, so they get a looser bound than k1 and
// the tangential terms; the projection comparison below is what bounds their combined effect.
constexpr std::array<double, 5> kDistortionTolerance = {0.005, 0.03, 5e-4, 5e-4, 0.03};

void ExpectIntrinsicsNear(const camera::Intrinsics& got, const camera::Intrinsics& want,
                          double pixel_tolerance) {
  EXPECT_NEAR(got.fx, want.fx, pixel_tolerance);
  EXPECT_NEAR(got.fy, want.fy, pixel_tolerance);
  EXPECT_NEAR(got.cx, want.cx, pixel_tolerance);
  EXPECT_NEAR(got.cy, want.cy, pixel_tolerance);
  for (size_t i = 0; i < 5; ++i)
    EXPECT_NEAR(got.distortion[i], want.distortion[i], kDistortionTolerance[i])
        << "coefficient " << i;
  // What matters downstream: where rays land. Compare projections over the whole image.
  double worst = 0;
  for (double x = -0.5; x <= 0.5; x += 0.05) {
    for (double y = -0.38; y <= 0.38; y += 0.04) {
      const Eigen::Vector3d p(x, y, 1);
      worst = std::max(worst, (*got.Project(p) - *want.Project(p)).norm());
    }
  }
  EXPECT_LT(worst, 0.25) << "worst projection difference over the image (px)";
}

TEST(IntrinsicsCalibration, RecoversTheRenderingCamera) {
  const Chessboard board = kBoard;
  const SyntheticSet& set = SpreadSet();
  const IntrinsicsCalibration result = CalibrateIntrinsics(set.views, board);
  const camera::Intrinsics truth = TestIntrinsics();
  std::cout << "synthetic: fx " << result.intrinsics.fx - truth.fx << " fy "
            << result.intrinsics.fy - truth.fy << " cx " << result.intrinsics.cx - truth.cx
            << " cy " << result.intrinsics.cy - truth.cy << " px off, rms " << result.report.rms_px
            << " px, coverage " << result.report.coverage << "\n";
  ExpectIntrinsicsNear(result.intrinsics, truth, 0.4);
  EXPECT_LT(result.report.rms_px, 0.07);
  EXPECT_GT(result.report.coverage, 0.85);
  ASSERT_EQ(result.report.views.size(), set.views.size());
  for (size_t i = 0; i < set.views.size(); ++i) {
    const ViewReport& view = result.report.views[i];
    EXPECT_FALSE(view.rejected) << view.name;
    EXPECT_LT(view.rms_px, 0.1) << view.name;
    // Per-view poses, origin and orientation (detection fixes the corner order).
    EXPECT_LT((view.T_cam_board.translation() - set.poses[i].translation()).norm(), 1e-3)
        << view.name;
    EXPECT_LT(
        Eigen::AngleAxisd(view.T_cam_board.linear().transpose() * set.poses[i].linear()).angle(),
        0.2 * M_PI / 180)
        << view.name;
  }
}

// The real set in miniature: 8 views of one board from a camera without distortion,
// corners with 0.3 px of noise. The full model fits the noise (k3 of several units); the
// held-out choice takes fewer terms and lands its rays nearer the truth over the whole image.
TEST(IntrinsicsCalibration, FewNoisyViewsChooseFewerDistortionTerms) {
  camera::Intrinsics truth = TestIntrinsics();
  truth.distortion = {};
  const std::vector<cv::Point3f> corners3d = kBoard.CornerPoints();
  const cv::Matx33d K(truth.fx, 0, truth.cx, 0, truth.fy, truth.cy, 0, 0, 1);
  cv::RNG noise(11);
  std::vector<BoardDetection> views;
  for (const Eigen::Isometry3d& pose : SpreadBoardPoses(truth, kBoard, 8, 3)) {
    cv::Mat rvec, tvec;
    cv::eigen2cv(Eigen::Vector3d(Eigen::AngleAxisd(pose.linear()).angle() *
                                 Eigen::AngleAxisd(pose.linear()).axis()),
                 rvec);
    cv::eigen2cv(Eigen::Vector3d(pose.translation()), tvec);
    BoardDetection view{"noisy_" + std::to_string(views.size()), {truth.width, truth.height}, {}};
    cv::projectPoints(corners3d, rvec, tvec, K, cv::noArray(), view.corners);
    for (cv::Point2f& c : view.corners) {
      c += cv::Point2f(static_cast<float>(noise.gaussian(0.3)),
                       static_cast<float>(noise.gaussian(0.3)));
    }
    views.push_back(std::move(view));
  }
  IntrinsicsOptions full_model;
  full_model.choose_distortion_model = false;
  full_model.min_coverage = 0;
  IntrinsicsOptions chosen_model = full_model;
  chosen_model.choose_distortion_model = true;
  const IntrinsicsCalibration full = CalibrateIntrinsics(views, kBoard, full_model);
  const IntrinsicsCalibration chosen = CalibrateIntrinsics(views, kBoard, chosen_model);
  std::cout << "full k3 " << full.intrinsics.distortion[4] << "; chosen "
            << chosen.report.distortion_model << " (" << chosen.report.distortion_model_reason
            << ")\n";
  EXPECT_EQ(full.report.distortion_model, "k1 k2 p1 p2 k3");
  EXPECT_NE(chosen.report.distortion_model, "k1 k2 p1 p2 k3");
  const auto worst_projection_error = [&](const camera::Intrinsics& got) {
    double worst = 0;
    for (double x = -0.5; x <= 0.5; x += 0.05) {
      for (double y = -0.38; y <= 0.38; y += 0.04) {
        const Eigen::Vector3d p(x, y, 1);
        worst = std::max(worst, (*got.Project(p) - *truth.Project(p)).norm());
      }
    }
    return worst;
  };
  EXPECT_LT(worst_projection_error(chosen.intrinsics), worst_projection_error(full.intrinsics));
}

TEST(IntrinsicsCalibration, RejectsACorruptedView) {
  const Chessboard board = kBoard;
  std::vector<BoardDetection> views = SpreadSet().views;
  // A view whose corners moved by about 2 px in a fixed pseudo-random pattern (a bump of the
  // camera during exposure, a wrong detection).
  const size_t bad = 5;
  for (size_t k = 0; k < views[bad].corners.size(); ++k) {
    views[bad].corners[k].x += static_cast<float>(2.0 * std::sin(1.7 * static_cast<double>(k)));
    views[bad].corners[k].y += static_cast<float>(2.0 * std::cos(2.3 * static_cast<double>(k)));
  }
  const IntrinsicsCalibration result = CalibrateIntrinsics(views, board);
  for (size_t i = 0; i < views.size(); ++i)
    EXPECT_EQ(result.report.views[i].rejected, i == bad) << views[i].name;
  EXPECT_GT(result.report.views[bad].rms_px, 1.0);
  ASSERT_FALSE(result.report.warnings.empty());
  EXPECT_NE(result.report.warnings.back().find("synthetic_5"), std::string::npos);
  ExpectIntrinsicsNear(result.intrinsics, TestIntrinsics(), 0.4);

  // Without rejection the same set calibrates measurably worse: the rule is doing the work.
  IntrinsicsOptions keep_all;
  keep_all.outlier_factor = 1e9;
  const IntrinsicsCalibration polluted = CalibrateIntrinsics(views, board, keep_all);
  EXPECT_GT(polluted.report.rms_px, 3 * result.report.rms_px);
}

TEST(IntrinsicsCalibration, RefusesWhenTooFewViewsFit) {
  const Chessboard board = kBoard;
  std::vector<BoardDetection> views(SpreadSet().views.begin(), SpreadSet().views.begin() + 6);
  for (size_t v : {1u, 3u}) {
    for (size_t k = 0; k < views[v].corners.size(); ++k)
      views[v].corners[k].x += static_cast<float>(3.0 * std::sin(0.9 * static_cast<double>(k + v)));
  }
  try {
    CalibrateIntrinsics(views, board);
    FAIL() << "expected a refusal";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("at least 5 needed"), std::string::npos) << message;
    EXPECT_NE(message.find("synthetic_"), std::string::npos) << message;
  }
}

TEST(IntrinsicsCalibration, RefusesCornersBunchedInOneImageCorner) {
  const Chessboard board = kBoard;
  const SyntheticSet set =
      DetectRendered(CornerBoardPoses(TestIntrinsics(), board, 6, 0.5, 11), board);
  try {
    CalibrateIntrinsics(set.views, board);
    FAIL() << "expected a coverage refusal";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cover only"), std::string::npos) << e.what();
  }
  // The same views pass when the threshold is lowered, and report the small coverage.
  IntrinsicsOptions lenient;
  lenient.min_coverage = 0;
  const IntrinsicsCalibration result = CalibrateIntrinsics(set.views, board, lenient);
  EXPECT_LE(result.report.coverage, 0.25 + 1e-9);
  ASSERT_FALSE(result.report.warnings.empty());
  EXPECT_NE(result.report.warnings.front().find("cover"), std::string::npos);
}

TEST(IntrinsicsCalibration, NamesBadViews) {
  const Chessboard board = kBoard;
  std::vector<BoardDetection> views = SpreadSet().views;
  views[2].corners.pop_back();
  EXPECT_THROW(
      {
        try {
          CalibrateIntrinsics(views, board);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("synthetic_2"), std::string::npos) << e.what();
          throw;
        }
      },
      std::invalid_argument);
  views = SpreadSet().views;
  views[4].corners[7].x = std::nanf("");
  EXPECT_THROW(
      {
        try {
          CalibrateIntrinsics(views, board);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("synthetic_4"), std::string::npos) << e.what();
          throw;
        }
      },
      std::invalid_argument);
  views = SpreadSet().views;
  views[3].image_size = cv::Size(800, 600);
  EXPECT_THROW(CalibrateIntrinsics(views, board), std::invalid_argument);
  views = SpreadSet().views;
  views.resize(3);
  EXPECT_THROW(CalibrateIntrinsics(views, board), std::runtime_error);
}

TEST(BoardPose, SolvePnPRecoversRenderedPoseAndNamesBadInput) {
  const Chessboard board = kBoard;
  const SyntheticSet& set = SpreadSet();
  const camera::Intrinsics truth = TestIntrinsics();
  const BoardPose pose = EstimateBoardPose(board.CornerPoints(), set.views[0].corners, truth, "v0");
  EXPECT_LT(pose.rms_px, 0.08);
  EXPECT_LT((pose.T_cam_board.translation() - set.poses[0].translation()).norm(), 5e-4);
  EXPECT_LT(
      Eigen::AngleAxisd(pose.T_cam_board.linear().transpose() * set.poses[0].linear()).angle(),
      0.2 * M_PI / 180);

  std::vector<cv::Point2f> short_corners(set.views[0].corners.begin(),
                                         set.views[0].corners.begin() + 10);
  try {
    EstimateBoardPose(board.CornerPoints(), short_corners, truth, "view_x");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("view_x"), std::string::npos);
  }
  camera::Intrinsics bad = truth;
  bad.fx = std::nan("");
  EXPECT_THROW(EstimateBoardPose(board.CornerPoints(), set.views[0].corners, bad, "v"),
               std::invalid_argument);
}

}  // namespace
}  // namespace avc::calibration
