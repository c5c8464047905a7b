// The report's coverage curve: captures in order, framing frames left out, each placed by the
// calibration from its reported pose, scored on the ground truth.

#include "report/report_coverage.h"

#include <gtest/gtest.h>

#include <string>

#include "core/kinematics/row_major_pose.h"
#include "tests/report/report_test_scan.h"

namespace avc::report {
namespace {

// A calibration whose flange is the camera and whose base is the table: a capture's reported
// flange pose is then the camera's pose in the world at table angle 0.
calibration::CellCalibration CameraIsFlange() {
  calibration::CellCalibration calibration;
  calibration.intrinsics = testing::LookingAtOrigin("x", {1, 0, 0}).camera.intrinsics;
  return calibration;
}

orchestrator::CaptureRecord CaptureAt(int index, const std::string& phase, bool kept,
                                      const Eigen::Vector3d& eye) {
  orchestrator::CaptureRecord c;
  c.index = index;
  c.phase = phase;
  c.kept = kept;
  const camera::Camera camera = testing::LookingAtOrigin("x", eye).camera;
  kinematics::RowMajorFromIsometry(camera.T_cam_world.inverse(), c.reported_T_base_flange.data());
  return c;
}

ReportInputs SheetSeenFromFourSides() {
  ReportInputs in;
  in.ground_truth = testing::WavySheet(8);  // open and seen from above: no self-occlusion
  in.calibration = CameraIsFlange();
  in.scan.emplace();
  // Out of order on purpose; index 1 is a framing frame (not counted), index 3 was pruned.
  in.scan->captures = {CaptureAt(4, "active", true, {0.05, 0.05, 0.4}),
                       CaptureAt(0, "initial", true, {0.4, -0.1, 0.25}),
                       CaptureAt(1, "frame", false, {0.3, 0.3, 0.3}),
                       CaptureAt(2, "initial", true, {-0.2, 0.35, 0.3}),
                       CaptureAt(3, "initial", false, {-0.3, -0.3, 0.2})};
  return in;
}

TEST(ReportCoverage, GrowsWithEachImageInCaptureOrderAndScoresTheKeptViews) {
  const std::optional<CoverageCurve> curve = CoverageOfCaptures(SheetSeenFromFourSides());
  ASSERT_TRUE(curve.has_value());
  ASSERT_EQ(curve->after.size(), 4u);  // the frame is not an image of the scan
  EXPECT_GT(curve->samples, 100u);
  EXPECT_EQ(curve->after[0], 0);  // one and two views cannot give the three a sample needs
  EXPECT_EQ(curve->after[1], 0);
  EXPECT_GT(curve->after[2], 0.1);
  EXPECT_GT(curve->after[3], curve->after[2]) << "the view from above adds a third view to more";
  for (size_t k = 1; k < curve->after.size(); ++k) EXPECT_GE(curve->after[k], curve->after[k - 1]);
  EXPECT_LE(curve->after.back(), 1.0);
  EXPECT_EQ(curve->kept, 3);
  EXPECT_GT(curve->kept_fraction, 0);
  EXPECT_LT(curve->kept_fraction, curve->after.back()) << "the pruned view counted for some";
  EXPECT_LE(curve->kept_fraction, curve->after.back());
}

TEST(ReportCoverage, TheSectionDrawsTheCurveOrSaysWhyNot) {
  const std::string html = CoverageSection(SheetSeenFromFourSides());
  EXPECT_NE(html.find("<polyline"), std::string::npos);
  EXPECT_NE(html.find("kept: 3 images"), std::string::npos);
  ReportInputs no_truth = SheetSeenFromFourSides();
  no_truth.ground_truth.reset();
  EXPECT_FALSE(CoverageOfCaptures(no_truth).has_value());
  EXPECT_NE(CoverageSection(no_truth).find("No ground truth"), std::string::npos);
}

}  // namespace
}  // namespace avc::report
