// Thin organs from the plant proxy: which voxels are thin, their surface, and how it replaces
// Algorithm 3's faces there.

#include "core/surface/thin_organs.h"

#include <gtest/gtest.h>

#include "core/surface/mesh_topology.h"

namespace avc::surface {
namespace {

constexpr double kVoxel = 0.002;

Eigen::Vector3f Centre(int x, int y, int z) {
  return (kVoxel * (Eigen::Vector3d(x, y, z).array() + 0.5)).matrix().cast<float>();
}

// A slab 12 x 12 x 5 voxels (a pot or a leaf's hull) with a one-voxel stem 20 voxels tall on it.
std::vector<Eigen::Vector3f> SlabWithStem() {
  std::vector<Eigen::Vector3f> centres;
  for (int z = 0; z < 5; ++z) {
    for (int y = 0; y < 12; ++y) {
      for (int x = 0; x < 12; ++x) centres.push_back(Centre(x, y, z));
    }
  }
  for (int z = 5; z < 25; ++z) centres.push_back(Centre(6, 6, z));
  return centres;
}

double Area(const geometry::Mesh& mesh) {
  double area = 0;
  for (const Eigen::Vector3i& f : mesh.faces) {
    const Eigen::Vector3f a = mesh.vertices[f[1]] - mesh.vertices[f[0]];
    const Eigen::Vector3f b = mesh.vertices[f[2]] - mesh.vertices[f[0]];
    area += 0.5 * a.cross(b).norm();
  }
  return area;
}

TEST(ThinOrgans, FindsTheStemAndNotTheSlabItStandsOn) {
  const std::vector<Eigen::Vector3i> thin = ThinVoxels(SlabWithStem(), kVoxel, {});
  // The slab's middle layer is 3 voxels deep (a core), and one layer higher under the stem,
  // which covers the slab's top there; the stem's first voxel is within reach of that core and
  // counts as the slab's.
  ASSERT_EQ(thin.size(), 19u);
  for (const Eigen::Vector3i& v : thin) {
    EXPECT_EQ(v.x(), 6);
    EXPECT_EQ(v.y(), 6);
    EXPECT_GE(v.z(), 6);
  }
  // A proxy with no bulky core is thin throughout.
  std::vector<Eigen::Vector3f> stem;
  for (int z = 0; z < 10; ++z) stem.push_back(Centre(0, 0, z));
  EXPECT_EQ(ThinVoxels(stem, kVoxel, {}).size(), 10u);
  ThinOrganOptions bad;
  bad.inward_voxels = 1.5;
  EXPECT_THROW(ThinVoxels(stem, kVoxel, bad), std::invalid_argument);
  EXPECT_THROW(ThinVoxels(stem, 0.0, {}), std::invalid_argument);
}

TEST(ThinOrgans, AVoxelsSurfaceIsClosedAndFacesOutwards) {
  const std::vector<Eigen::Vector3i> one = {Eigen::Vector3i(0, 0, 0)};
  const geometry::Mesh cube = VoxelSurface(one, one, kVoxel, 0, 0.0);
  ASSERT_EQ(cube.faces.size(), 12u);
  EXPECT_NEAR(Area(cube), 6 * kVoxel * kVoxel, 1e-6 * 6 * kVoxel * kVoxel);
  int pieces = 0;
  FaceComponents(cube, &pieces);
  EXPECT_EQ(pieces, 1);
  const Eigen::Vector3f centre = Centre(0, 0, 0);
  for (const Eigen::Vector3i& f : cube.faces) {
    const Eigen::Vector3f normal = (cube.vertices[f[1]] - cube.vertices[f[0]])
                                       .cross(cube.vertices[f[2]] - cube.vertices[f[0]]);
    const Eigen::Vector3f out =
        (cube.vertices[f[0]] + cube.vertices[f[1]] + cube.vertices[f[2]]) / 3.0f - centre;
    EXPECT_GT(normal.dot(out), 0.0f);
  }
  // Against an occupied neighbour the face stays open; moved in, the surface shrinks.
  const std::vector<Eigen::Vector3i> pair = {Eigen::Vector3i(0, 0, 0), Eigen::Vector3i(1, 0, 0)};
  EXPECT_EQ(VoxelSurface(one, pair, kVoxel, 0, 0.0).faces.size(), 10u);
  EXPECT_LT(Area(VoxelSurface(one, one, kVoxel, 0, 0.25)), Area(cube));
}

TEST(ThinOrgans, ReplaceAlgorithm3sFacesOnTheStemAndKeepTheRest) {
  geometry::Mesh mesh;
  // A sliver on the stem and a leaf triangle well away from it.
  const Eigen::Vector3f on_stem = Centre(6, 6, 15);
  mesh.vertices = {on_stem,
                   on_stem + Eigen::Vector3f(0.0005f, 0, 0),
                   on_stem + Eigen::Vector3f(0, 0.0005f, 0),
                   Centre(0, 0, 4),
                   Centre(2, 0, 4),
                   Centre(0, 2, 4)};
  mesh.faces = {Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(3, 4, 5)};
  mesh.face_labels = {0, 1};
  const size_t added = AddThinOrgans(mesh, SlabWithStem(), kVoxel, {}, 2);
  EXPECT_GT(added, 0u);
  EXPECT_TRUE(mesh.Validate().empty()) << mesh.Validate();
  ASSERT_EQ(mesh.faces.size(), 1 + added);
  EXPECT_EQ(mesh.face_labels[0], 1);  // the leaf triangle, kept
  EXPECT_EQ(mesh.face_labels.back(), 2);
  int pieces = 0;
  FaceComponents(mesh, &pieces);
  EXPECT_EQ(pieces, 2);  // the leaf triangle and the stem's tube
  // Without thin parts nothing changes.
  geometry::Mesh copy = mesh;
  EXPECT_EQ(AddThinOrgans(copy, {}, kVoxel, {}, 3), 0u);
  EXPECT_EQ(copy.faces.size(), mesh.faces.size());
}

}  // namespace
}  // namespace avc::surface
