// The simulated calibration chessboard: its geometry and, rendered through the cell's distorted
// camera, OpenCV finds every inner corner where the board model says it projects.

#include "sim/scene/chessboard_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "sim/cell/cell_truth.h"
#include "sim/cell/view_selection.h"
#include "sim/render/renderer.h"

namespace avc::sim {
namespace {

TEST(ChessboardScene, SquaresMarginLabelsAndCorners) {
  ChessboardSpec spec;
  const Scene scene = ChessboardScene(spec);
  EXPECT_TRUE(scene.mesh.Validate().empty()) << scene.mesh.Validate();
  EXPECT_EQ(scene.mesh.faces.size(), 2u * (10 * 7 + 4));
  for (const int32_t label : scene.mesh.face_labels) EXPECT_EQ(label, geometry::labels::kTarget);
  EXPECT_NEAR(geometry::SurfaceArea(scene.mesh), (10 * 0.025 + 0.05) * (7 * 0.025 + 0.05), 1e-6);
  const std::vector<Eigen::Vector3d> corners = ChessboardCorners(spec);
  ASSERT_EQ(corners.size(), 54u);
  EXPECT_EQ(corners[1], Eigen::Vector3d(0.025, 0, 0));  // along a row first, as OpenCV orders
  EXPECT_EQ(corners[9], Eigen::Vector3d(0, 0.025, 0));
  // Centred on the turntable axis, face up.
  EXPECT_EQ(spec.T_world_board.linear() * Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d middle = spec.T_world_board * (0.5 * (corners.front() + corners.back()));
  EXPECT_LT(middle.norm(), 1e-12);

  spec.inner_rows = spec.inner_cols;
  EXPECT_THROW(ChessboardScene(spec), std::invalid_argument);
}

TEST(ChessboardScene, OpenCvFindsTheRenderedCornersWhereTheModelProjectsThem) {
  const ChessboardSpec spec;
  const Scene scene = ChessboardScene(spec);
  const CellTruth cell = NominalCell();  // 1280x960 with barrel distortion
  const Eigen::Vector3d target(0, 0, 0);
  const Eigen::Vector3d centre =
      ViewpointOnSphere(target, 0.45, 60 * std::numbers::pi / 180, RobotAzimuth(cell));
  camera::Camera camera;
  camera.intrinsics = cell.intrinsics;
  camera.T_cam_world =
      LookAtPose(centre, target, cell.T_base_table.inverse().translation()).inverse();
  RenderOptions options;
  options.background.kind = Background::Kind::kPlain;
  options.samples_per_pixel_axis = 4;
  const RenderResult result = Render(scene, camera, options);

  cv::Mat gray;
  cv::cvtColor(result.color, gray, cv::COLOR_BGR2GRAY);
  std::vector<cv::Point2f> found;
  ASSERT_TRUE(cv::findChessboardCornersSB(gray, cv::Size(spec.inner_cols, spec.inner_rows), found,
                                          cv::CALIB_CB_ACCURACY));
  const std::vector<Eigen::Vector3d> corners = ChessboardCorners(spec);
  ASSERT_EQ(found.size(), corners.size());
  // The detector orders corners as the board model does, up to the pattern's 180 degree
  // symmetry: compare with both orders.
  double error_forward = 0, error_reversed = 0, sum_sq_forward = 0, sum_sq_reversed = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2d expected = camera.Project(spec.T_world_board * corners[i]).value();
    const auto& a = found[i];
    const auto& b = found[corners.size() - 1 - i];
    const double forward = (expected - Eigen::Vector2d(a.x, a.y)).norm();
    const double reversed = (expected - Eigen::Vector2d(b.x, b.y)).norm();
    error_forward = std::max(error_forward, forward);
    error_reversed = std::max(error_reversed, reversed);
    sum_sq_forward += forward * forward;
    sum_sq_reversed += reversed * reversed;
  }
  // Sub-pixel agreement: what the detector's own bias on an anti-aliased, obliquely seen board
  // allows (an error in the board model or the renderer would be whole pixels or squares off).
  const double rms = std::sqrt(std::min(sum_sq_forward, sum_sq_reversed) / corners.size());
  EXPECT_LT(rms, 0.1) << "corner RMS error in pixels";
  EXPECT_LT(std::min(error_forward, error_reversed), 0.3) << "max corner error in pixels";
}

}  // namespace
}  // namespace avc::sim
