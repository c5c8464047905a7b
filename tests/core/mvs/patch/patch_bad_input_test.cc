// Bad inputs to the patch MVS give std::invalid_argument naming the view and field.

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "core/mvs/patch/patch_mvs.h"
#include "tests/core/mvs/patch/patch_test_scenes.h"

namespace avc::mvs {
namespace {

std::vector<dataset::View> Views() { return testing::TexturedPlaneViews(3, 64, 48, 0.5, 0.3, 3); }

void ExpectRefused(const std::vector<dataset::View>& views, const std::string& words,
                   const MvsBounds& bounds = {}, const PatchMvsOptions& options = {}) {
  try {
    RunPatchMvs(views, bounds, options);
    FAIL() << "expected std::invalid_argument mentioning '" << words << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(PatchMvsBadInput, RefusesTooFewViews) {
  ExpectRefused({}, "at least 2 views");
  auto views = Views();
  views.resize(1);
  ExpectRefused(views, "at least 2 views");
}

TEST(PatchMvsBadInput, RefusesEmptyImage) {
  auto views = Views();
  views[1].image = cv::Mat();
  ExpectRefused(views, "view 1 ('plane_1'): image is empty");
}

TEST(PatchMvsBadInput, RefusesWrongImageType) {
  auto views = Views();
  cv::Mat grey(views[0].image.size(), CV_8UC1, cv::Scalar(0));
  views[0].image = grey;
  ExpectRefused(views, "view 0 ('plane_0'): image must be CV_8UC3");
}

TEST(PatchMvsBadInput, RefusesSizeMismatch) {
  auto views = Views();
  views[2].camera.intrinsics.width = 80;
  ExpectRefused(views, "view 2 ('plane_2'): image is 64x48 but the camera is 80x48");
}

TEST(PatchMvsBadInput, RefusesDistortion) {
  auto views = Views();
  views[1].camera.intrinsics.distortion[0] = 0.1;
  ExpectRefused(views, "view 1 ('plane_1'): camera has lens distortion");
}

TEST(PatchMvsBadInput, RefusesNanPose) {
  auto views = Views();
  views[0].camera.T_cam_world.translation().x() = std::numeric_limits<double>::quiet_NaN();
  ExpectRefused(views, "view 0 ('plane_0'): camera pose is not finite");
}

TEST(PatchMvsBadInput, RefusesEmptyAndMisshapenMasks) {
  auto views = Views();
  views[2].mask.setTo(0);
  ExpectRefused(views, "view 2 ('plane_2'): mask has no plant pixel");
  views = Views();
  views[1].mask = cv::Mat(10, 10, CV_8UC1, cv::Scalar(255));
  ExpectRefused(views, "view 1 ('plane_1'): mask must be empty or CV_8UC1 of the image size");
}

TEST(PatchMvsBadInput, RefusesBadBoundsAndOptions) {
  MvsBounds bounds;
  bounds.occupied_centres.push_back(Eigen::Vector3f::Zero());
  ExpectRefused(Views(), "bounds.voxel_size must be positive", bounds);
  bounds.voxel_size = 0.01;
  bounds.occupied_centres.push_back(
      Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN()));
  ExpectRefused(Views(), "bounds.occupied_centres[1] is not finite", bounds);
  PatchMvsOptions options;
  options.window = 4;
  ExpectRefused(Views(), "PatchMvsOptions.window", {}, options);
  options = {};
  options.ncc_threshold = std::numeric_limits<double>::quiet_NaN();
  ExpectRefused(Views(), "PatchMvsOptions.ncc_threshold", {}, options);
}

TEST(PatchMvsBadInput, UntexturedViewsGiveNoPointsNotACrash) {
  auto views = Views();
  for (auto& v : views) v.image.setTo(cv::Scalar(90, 90, 90));
  const MvsPoints points = RunPatchMvs(views, {}, PatchMvsOptions{});
  EXPECT_EQ(points.size(), 0u);
}

}  // namespace
}  // namespace avc::mvs
