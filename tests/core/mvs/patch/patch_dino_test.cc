// The patch MVS on the Middlebury dinoSparseRing (16 real 640x480 images of an untextured
// ceramic dino), at pyramid level 1 (320x240) to keep the test fast: the points lie in the README's
// tight box and inside the silhouettes of the images that see them.

#include <gtest/gtest.h>

#include "core/dataset/dataset_reader.h"
#include "core/mvs/patch/patch_mvs.h"
#include "tests/core/mvs/patch/patch_test_scenes.h"
#include "tests/support/test_support.h"

namespace avc::mvs {
namespace {

TEST(PatchMvsDino, PointsInsideTheBoxAndTheSilhouettes) {
  const auto dir = avc::testing::SharedDataDir() / "middlebury" / "dinoSparseRing";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no dino data at " << dir;
  auto set = dataset::ReadDataset(dir);
  std::vector<cv::Mat> silhouettes;
  for (auto& view : set.views) {
    silhouettes.push_back(testing::DinoSilhouette(view.image));
    view.mask = silhouettes.back();
  }
  const MvsBounds hull =
      testing::VisualHull(set.views, {-0.07, -0.025, -0.065}, {0.02, 0.075, 0.025}, 0.002);
  PatchMvsOptions options;
  options.level = 1;
  const MvsPoints points = RunPatchMvs(set.views, hull, options);
  ASSERT_EQ(points.Validate(), "");
  // Measured at level 1: 29,589 points, 99.4 % inside every silhouette of the images that see
  // them (PMVS2 at level 1: 20,909 points, 85.4 %).
  EXPECT_GT(points.size(), 26000u);
  EXPECT_GT(testing::InsideFraction(points, set.views, silhouettes), 0.98);
  const Eigen::Vector3f lo(-0.061897f, -0.018874f, -0.057845f);
  const Eigen::Vector3f hi(0.010897f, 0.068227f, 0.015495f);
  const float margin = 0.003f;  // 3 mm: the points' noise plus the hull voxel
  size_t outside = 0;
  for (const auto& p : points.cloud.positions) {
    outside += ((p.array() < lo.array() - margin) || (p.array() > hi.array() + margin)).any();
  }
  EXPECT_LT(outside, points.size() / 200);
  for (size_t i = 0; i < points.size(); ++i) {
    // Normals face the cameras that see the point.
    const auto& cam = set.views[points.views[i][0]].camera;
    const Eigen::Vector3f to_camera = cam.Centre().cast<float>() - points.cloud.positions[i];
    ASSERT_GT(to_camera.dot(points.cloud.normals[i]), 0) << "point " << i;
  }
}

}  // namespace
}  // namespace avc::mvs
