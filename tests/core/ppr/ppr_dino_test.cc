// The proxy on the Middlebury dinoSparseRing: automatic bounds, masks by the dataset's recipe,
// and the carved voxels against the dataset's tight bounding box.

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgproc.hpp>

#include "core/dataset/dataset_reader.h"
#include "core/ppr/plant_proxy.h"
#include "core/ppr/proxy_bounds.h"
#include "core/segmentation/threshold_silhouette.h"
#include "tests/support/test_support.h"

namespace avc::ppr {
namespace {

const std::filesystem::path kDino = avc::testing::SharedDataDir() / "middlebury" / "dinoSparseRing";

// The README's silhouette recipe: grey threshold 0.19, dilate 10 px, erode 7 px (discs).
cv::Mat DinoMask(const cv::Mat& image) {
  return segmentation::ThresholdSilhouette(image, 0.19, 10, 7);
}

TEST(PlantProxyDino, CarvedVoxelsFillTheTightBoundingBox) {
  if (!std::filesystem::exists(kDino)) {
    GTEST_SKIP() << kDino << " is absent (shared Middlebury data)";
  }
  dataset::ViewSet set = dataset::ReadDataset(kDino);
  ASSERT_EQ(set.views.size(), 16u);
  for (auto& view : set.views) view.mask = DinoMask(view.image);

  const Eigen::AlignedBox3d box = BoundsFromViews(set.views);
  const Eigen::AlignedBox3d tight(Eigen::Vector3d(-0.061897, -0.018874, -0.057845),
                                  Eigen::Vector3d(0.010897, 0.068227, 0.015495));
  PlantProxy proxy(box);  // defaults: k = 1, m = 2, longest edge / 256, one increase
  for (const auto& view : set.views) proxy.AddView(view);
  proxy.IncreaseResolution();
  const double voxel = proxy.voxel_size();
  std::printf("auto box %.4f..%.4f %.4f..%.4f %.4f..%.4f, voxel %.5f m\n", box.min().x(),
              box.max().x(), box.min().y(), box.max().y(), box.min().z(), box.max().z(), voxel);

  // The automatic box holds the dino, and not much more.
  EXPECT_TRUE(box.contains(tight));
  EXPECT_LT(box.volume(), 4.5 * tight.volume());  // measured 3.7x

  // Occupied voxels stay within the tight box plus the slack of a one-ring visual hull: its
  // cones are not cut off along the ring axis (measured 30.5 mm at most, along z, with k = 0
  // as well as k = 1).
  const Eigen::AlignedBox3d occupied = proxy.OccupiedBounds();
  const Eigen::AlignedBox3d allowed(tight.min().array() - 0.032, tight.max().array() + 0.032);
  std::printf("occupied %.4f..%.4f %.4f..%.4f %.4f..%.4f\n", occupied.min().x(), occupied.max().x(),
              occupied.min().y(), occupied.max().y(), occupied.min().z(), occupied.max().z());
  EXPECT_TRUE(allowed.contains(occupied));
  // ... and reach close to every face of it: the whole dino survived.
  EXPECT_TRUE((occupied.min().array() <= tight.min().array() + 4 * voxel).all());
  EXPECT_TRUE((occupied.max().array() >= tight.max().array() - 4 * voxel).all());

  // The hull fills a fraction of the tight box's volume; measured 0.325 with k = 1.
  const double fill =
      static_cast<double>(proxy.Counts().occupied) * std::pow(voxel, 3) / tight.volume();
  std::printf("occupied / tight box volume: %.3f\n", fill);
  EXPECT_GT(fill, 0.25);
  EXPECT_LT(fill, 0.40);
}

}  // namespace
}  // namespace avc::ppr
