// Chessboard detection: sub-pixel corners on a rendered board, and named errors for bad images.

#include "core/calibration/board/chessboard_detection.h"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "core/calibration/board/board_pose.h"
#include "tests/core/calibration/board/synthetic_board_views.h"
#include "tests/support/test_support.h"

namespace avc::calibration {
namespace {

template <class Error, class F>
std::string ExpectErrorMessage(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "unexpected exception type: " << e.what();
    return {};
  }
  ADD_FAILURE() << "no exception";
  return {};
}

TEST(ChessboardDetection, FindsRenderedCornersToSubPixelInBoardOrder) {
  const Chessboard board;
  const camera::Intrinsics intrinsics = testing::TestIntrinsics();
  auto poses = testing::SpreadBoardPoses(intrinsics, board, 3, 21);
  // Upside down in the image too: the order must follow the board, not the image.
  Eigen::Isometry3d half_turn = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d centre((board.cols - 1) * board.square_size / 2,
                               (board.rows - 1) * board.square_size / 2, 0);
  half_turn.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  half_turn.translation() = centre - half_turn.linear() * centre;
  for (int i = 0; i < 3; ++i) poses.push_back(poses[static_cast<size_t>(i)] * half_turn);
  for (const auto& T : poses) {
    const cv::Mat image = testing::RenderBoard(intrinsics, T, board);
    const BoardDetection detection = DetectChessboard(image, board, "rendered");
    ASSERT_EQ(detection.corners.size(), 54u);
    EXPECT_EQ(detection.image_size, cv::Size(640, 480));
    std::vector<cv::Point2f> truth;
    cv::Mat rvec, tvec;
    cv::Mat R(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) R.at<double>(r, c) = T.linear()(r, c);
    cv::Rodrigues(R, rvec);
    tvec =
        (cv::Mat_<double>(3, 1) << T.translation().x(), T.translation().y(), T.translation().z());
    cv::projectPoints(board.CornerPoints(), rvec, tvec, CameraMatrix(intrinsics),
                      DistortionVector(intrinsics), truth);
    // Same order as CornerPoints: the first corner is the one next to the dark square.
    double worst = 0;
    for (size_t k = 0; k < truth.size(); ++k)
      worst = std::max(worst, static_cast<double>(cv::norm(detection.corners[k] - truth[k])));
    EXPECT_LT(worst, 0.15) << "worst corner error (px)";
  }
}

TEST(ChessboardDetection, NamesTheImageWhenTheBoardIsMissing) {
  const cv::Mat blank(480, 640, CV_8U, cv::Scalar(128));
  const std::string message =
      ExpectErrorMessage<std::runtime_error>([&] { DetectChessboard(blank, {}, "blank.png"); });
  EXPECT_NE(message.find("blank.png"), std::string::npos) << message;
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(ChessboardDetection, RejectsBadImagesAndBoards) {
  EXPECT_NE(ExpectErrorMessage<std::invalid_argument>([] {
              DetectChessboard(cv::Mat(), {}, "empty.png");
            }).find("empty.png"),
            std::string::npos);
  EXPECT_NE(ExpectErrorMessage<std::invalid_argument>([] {
              DetectChessboard(cv::Mat(48, 64, CV_32F, cv::Scalar(0)), {}, "float.tif");
            }).find("float.tif"),
            std::string::npos);
  Chessboard bad_board;
  bad_board.square_size = -1;
  EXPECT_NE(ExpectErrorMessage<std::invalid_argument>([&] {
              DetectChessboard(cv::Mat(48, 64, CV_8U, cv::Scalar(0)), bad_board, "x.png");
            }).find("square size"),
            std::string::npos);
  Chessboard square_board{7, 7, 0.02};
  EXPECT_FALSE(square_board.Validate().empty());
}

TEST(ChessboardDetection, NamesUnreadableFiles) {
  avc::testing::TempDir dir;
  const auto missing = dir / "missing.png";
  EXPECT_NE(ExpectErrorMessage<std::runtime_error>([&] {
              DetectChessboardInFile(missing, {});
            }).find("missing.png"),
            std::string::npos);
  const auto corrupt = dir / "corrupt.png";
  avc::testing::WriteFile(corrupt, "\x89PNG\r\n\x1a\nnot really a png");
  EXPECT_NE(ExpectErrorMessage<std::runtime_error>([&] {
              DetectChessboardInFile(corrupt, {});
            }).find("corrupt.png"),
            std::string::npos);
}

TEST(Chessboard, CornerPointsAreRowMajorInMetres) {
  const Chessboard board{9, 6, 0.025};
  const auto points = board.CornerPoints();
  ASSERT_EQ(points.size(), 54u);
  EXPECT_FLOAT_EQ(points[1].x, 0.025f);
  EXPECT_FLOAT_EQ(points[9].y, 0.025f);
  EXPECT_FLOAT_EQ(points[53].x, 0.2f);
  EXPECT_FLOAT_EQ(points[53].y, 0.125f);
  EXPECT_EQ(points[53].z, 0.f);
}

}  // namespace
}  // namespace avc::calibration
