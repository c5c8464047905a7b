// The proxy's surface patches and their visibility on a carved sphere: faces face outwards, the
// face area is the voxelised sphere's, and a view sees the patches turned to it and not those
// on the far side (ray casting through the proxy).

#include "services/planner/proxy_patches.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "services/planner/patch_visibility.h"
#include "tests/core/ppr/synthetic_views.h"

namespace avc::planner {
namespace {

constexpr double kRadius = 0.05;

ppr::PlantProxy CarvedSphere() {
  ppr::ProxyOptions options;
  options.final_voxel_size = 0.004;
  options.resolution_increases = 0;
  ppr::PlantProxy proxy(
      Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.08), Eigen::Vector3d::Constant(0.08)),
      options);
  for (const camera::Camera& camera : ppr::testing::RingCameras(12, 0.4)) {
    proxy.AddView(camera, ppr::testing::SphereMask(camera, Eigen::Vector3d::Zero(), kRadius));
  }
  return proxy;
}

TEST(ProxySurfacePatches, OutwardFacesCoverTheVoxelisedSphere) {
  const ppr::PlantProxy proxy = CarvedSphere();
  const std::vector<SurfacePatch> patches = ProxySurfacePatches(proxy);
  ASSERT_GT(patches.size(), 20u);
  size_t faces = 0, outward = 0;
  for (const SurfacePatch& patch : patches) {
    EXPECT_NEAR(patch.normal.cwiseAbs().maxCoeff(), 1.0, 1e-12);  // one of the six axes
    for (const Eigen::Vector3d& point : patch.points) {
      ++faces;
      outward += point.dot(patch.normal) > 0;
    }
  }
  EXPECT_GT(static_cast<double>(outward) / faces, 0.97);
  // Axis-aligned faces of a voxelised sphere add up to 1.5 times its area (the mean of
  // |nx| + |ny| + |nz| over a sphere); the carved hull is a little larger than the sphere.
  const double ratio = faces * std::pow(proxy.voxel_size(), 2) / (4 * M_PI * kRadius * kRadius);
  EXPECT_GT(ratio, 1.4);
  EXPECT_LT(ratio, 2.0);
}

TEST(PatchVisibility, AViewSeesTheNearSideAndNotTheFarSide) {
  const ppr::PlantProxy proxy = CarvedSphere();
  const std::vector<SurfacePatch> patches = ProxySurfacePatches(proxy);
  const camera::Camera camera =
      ppr::testing::LookAt(Eigen::Vector3d(0.4, 0, 0), Eigen::Vector3d::Zero());
  const PatchesSeen seen = PatchesSeenBy(proxy, patches, camera);
  size_t near_seen = 0, near = 0, far_seen = 0;
  for (size_t p = 0; p < patches.size(); ++p) {
    if (patches[p].normal.x() > 0.5 && patches[p].centre.x() > 0.02) {
      ++near;
      near_seen += seen[p];
    }
    if (patches[p].normal.x() < -0.5) far_seen += seen[p];
  }
  ASSERT_GT(near, 0u);
  EXPECT_EQ(near_seen, near);
  EXPECT_EQ(far_seen, 0u);  // behind the sphere: the rays hit it first

  PatchViewCounts counts;
  AddView(seen, &counts);
  AddView(seen, &counts);
  const std::vector<double> scores = PatchScores(counts);
  for (size_t p = 0; p < patches.size(); ++p) EXPECT_DOUBLE_EQ(scores[p], seen[p] * 2.0 / 3.0);
  RemoveView(seen, &counts);
  for (size_t p = 0; p < patches.size(); ++p) EXPECT_EQ(counts[p], seen[p]);
}

TEST(PatchVisibility, FacesSeenAgreeWithEachPatchsSeenFraction) {
  const ppr::PlantProxy proxy = CarvedSphere();
  const std::vector<SurfacePatch> patches = ProxySurfacePatches(proxy);
  const camera::Camera camera =
      ppr::testing::LookAt(Eigen::Vector3d(0.3, 0.2, 0.1), Eigen::Vector3d::Zero());
  const PatchesSeen faces = FacesSeenBy(proxy, patches, camera);
  size_t next = 0, partly_seen = 0;
  for (const SurfacePatch& patch : patches) {
    // One patch's sampled faces follow each other.
    const size_t sampled = SampledFaceCount(patch);
    ASSERT_GT(sampled, 0u);
    ASSERT_LE(sampled, VisibilityOptions{}.max_sampled_faces);
    ASSERT_LE(next + sampled, faces.size());
    size_t seen = 0;
    for (size_t k = 0; k < sampled; ++k) seen += faces[next++];
    const double fraction = SeenFraction(proxy, patch, camera);
    partly_seen += fraction > 0 && fraction < 1;
    EXPECT_DOUBLE_EQ(fraction, static_cast<double>(seen) / sampled);
  }
  EXPECT_EQ(next, faces.size());
  EXPECT_GT(partly_seen, 0u);  // the test sees patches at the sphere's rim
  // The patches' verdicts from the faces are PatchesSeenBy's.
  EXPECT_EQ(PatchesSeenFromFaces(patches, faces), PatchesSeenBy(proxy, patches, camera));
  EXPECT_THROW(PatchesSeenFromFaces(patches, PatchesSeen(faces.size() - 1)), std::invalid_argument);
}

}  // namespace
}  // namespace avc::planner
