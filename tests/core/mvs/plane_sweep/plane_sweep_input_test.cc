// Bad inputs to the plane sweep give std::invalid_argument naming the view and field at fault.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "core/mvs/plane_sweep/plane_sweep_mvs.h"
#include "core/mvs/plane_sweep/sweep_views.h"
#include "tests/core/mvs/plane_sweep/sweep_test_scenes.h"

namespace avc::mvs {
namespace {

void ExpectRefused(const std::function<void(std::vector<dataset::View>&)>& spoil,
                   const std::string& expected_words, const PlaneSweepOptions& options = {}) {
  sweep_test::TexturedPlane scene = sweep_test::MakeTexturedPlane(0.0, 1);
  spoil(scene.views);
  try {
    RunPlaneSweep(scene.views, scene.bounds, options);
    FAIL() << "accepted input that should fail with: " << expected_words;
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(expected_words), std::string::npos) << error.what();
  }
}

TEST(PlaneSweepInput, RefusesFewerThanTwoViews) {
  ExpectRefused([](auto& views) { views.resize(1); }, "at least 2 views");
  ExpectRefused([](auto& views) { views.clear(); }, "at least 2 views");
}

TEST(PlaneSweepInput, RefusesMissingImage) {
  ExpectRefused([](auto& views) { views[2].image = cv::Mat(); },
                "view 2 ('plane_2'): image is empty");
}

TEST(PlaneSweepInput, RefusesWrongImageType) {
  ExpectRefused([](auto& views) { views[1].image = cv::Mat(240, 320, CV_8UC1, cv::Scalar(0)); },
                "view 1 ('plane_1'): image is not 8-bit 3-channel");
}

TEST(PlaneSweepInput, RefusesImageCameraSizeMismatch) {
  ExpectRefused([](auto& views) { views[3].camera.intrinsics.width = 640; },
                "view 3 ('plane_3'): image is 320x240 but its camera is 640x240");
}

TEST(PlaneSweepInput, RefusesDistortion) {
  ExpectRefused([](auto& views) { views[0].camera.intrinsics.distortion[0] = 0.1; },
                "view 0 ('plane_0'): camera has lens distortion");
}

TEST(PlaneSweepInput, RefusesNanPoseAndIntrinsics) {
  ExpectRefused(
      [](auto& views) {
        views[4].camera.T_cam_world.translation().x() = std::numeric_limits<double>::quiet_NaN();
      },
      "view 4 ('plane_4'): camera pose T_cam_world is not finite");
  ExpectRefused([](auto& views) { views[4].camera.intrinsics.fx = std::nan(""); },
                "view 4 ('plane_4'): camera intrinsics: focal lengths");
}

TEST(PlaneSweepInput, RefusesEmptyOrMisshapenMask) {
  ExpectRefused([](auto& views) { views[1].mask.setTo(0); },
                "view 1 ('plane_1'): mask has no plant pixels");
  ExpectRefused([](auto& views) { views[1].mask = cv::Mat(10, 10, CV_8UC1, cv::Scalar(255)); },
                "view 1 ('plane_1'): mask is not CV_8UC1 of the image size");
}

TEST(PlaneSweepInput, RefusesBadOptionsAndBounds) {
  PlaneSweepOptions options;
  options.window = 4;
  ExpectRefused([](auto&) {}, "window 4", options);
  options = {};
  options.best_k = 5;
  ExpectRefused([](auto&) {}, "best_k 5", options);
  options = {};
  options.consistency_tolerance = std::nan("");
  ExpectRefused([](auto&) {}, "consistency_tolerance", options);

  sweep_test::TexturedPlane scene = sweep_test::MakeTexturedPlane(0.0, 1);
  MvsBounds bounds = scene.bounds;
  bounds.occupied_centres[5].x() = std::numeric_limits<float>::infinity();
  EXPECT_THROW(RunPlaneSweep(scene.views, bounds, {}), std::invalid_argument);
  bounds = scene.bounds;
  bounds.voxel_size = 0;
  EXPECT_THROW(RunPlaneSweep(scene.views, bounds, {}), std::invalid_argument);
}

TEST(PlaneSweepInput, EmptyMasksMeanEverywhere) {
  sweep_test::TexturedPlane scene = sweep_test::MakeTexturedPlane(0.0, 1);
  for (dataset::View& view : scene.views) view.mask = cv::Mat();
  const MvsPoints points = RunPlaneSweep(scene.views, scene.bounds, {});
  EXPECT_GT(points.size(), 1000u);
  EXPECT_EQ(points.Validate(), "");
}

TEST(PlaneSweepInput, AutomaticLevelMatchesThePatchMvsRule) {
  std::vector<dataset::View> views(2);
  views[0].image = cv::Mat(480, 640, CV_8UC3);
  views[1].image = cv::Mat(480, 640, CV_8UC3);
  EXPECT_EQ(ChooseSweepLevel(views, -1), 0);
  views[1].image = cv::Mat(960, 1280, CV_8UC3);
  EXPECT_EQ(ChooseSweepLevel(views, -1), 1);
  views[1].image = cv::Mat(3456, 5184, CV_8UC3);
  EXPECT_EQ(ChooseSweepLevel(views, -1), 3);
  EXPECT_EQ(ChooseSweepLevel(views, 2), 2);
}

TEST(PlaneSweepInput, ReportsProgressPerReferenceView) {
  const sweep_test::TexturedPlane scene = sweep_test::MakeTexturedPlane(0.0, 2);
  std::vector<std::pair<std::string, size_t>> calls;
  RunPlaneSweep(scene.views, scene.bounds, {},
                [&](const std::string& stage, size_t done, size_t total) {
                  if (stage == "plane sweep") {
                    EXPECT_EQ(total, scene.views.size());
                  }
                  calls.emplace_back(stage, done);
                });
  ASSERT_EQ(calls.size(), scene.views.size() + 2);
  EXPECT_EQ(calls[scene.views.size() - 1], std::make_pair(std::string("plane sweep"), size_t{5}));
  EXPECT_EQ(calls.back(), std::make_pair(std::string("fusion"), size_t{1}));
}

}  // namespace
}  // namespace avc::mvs
