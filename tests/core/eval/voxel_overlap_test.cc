// Voxel overlap of a proxy with a voxelised surface, on a flat sheet whose voxels are known.

#include "core/eval/voxel_overlap.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace avc::eval {
namespace {

constexpr double kVoxel = 0.01;

// A 10 cm square sheet inside the voxel layer 0 <= z < 1 cm: 10 x 10 voxels.
geometry::Mesh Sheet() {
  geometry::Mesh mesh;
  mesh.vertices = {{0, 0, 0.004f}, {0.1f, 0, 0.004f}, {0.1f, 0.1f, 0.004f}, {0, 0.1f, 0.004f}};
  mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

Eigen::Vector3f Centre(int i, int j, int k) {
  return (kVoxel * (Eigen::Vector3d(i, j, k).array() + 0.5)).matrix().cast<float>();
}

TEST(VoxelOverlap, CountsTheSheetsVoxelsAndTheProxysExtras) {
  std::vector<Eigen::Vector3f> proxy;
  for (int j = 0; j < 10; ++j) {
    for (int i = 0; i < 10; ++i) {
      if (j * 10 + i >= 20) proxy.push_back(Centre(i, j, 0));  // 20 sheet voxels missed
      if (i < 5) proxy.push_back(Centre(i, j, 1));             // 50 voxels above the sheet
    }
  }
  const VoxelOverlap overlap = CompareWithSurface(Sheet(), proxy, Eigen::Vector3d::Zero(), kVoxel);
  EXPECT_EQ(overlap.truth, 100u);
  EXPECT_EQ(overlap.proxy, 130u);
  EXPECT_EQ(overlap.both, 80u);
  EXPECT_NEAR(overlap.Iou(), 80.0 / 150.0, 1e-12);
  EXPECT_NEAR(overlap.Precision(), 80.0 / 130.0, 1e-12);
  EXPECT_NEAR(overlap.Recall(), 0.8, 1e-12);
}

TEST(VoxelOverlap, AShiftedGridSeesTheSheetInOtherVoxels) {
  // Origin half a voxel lower: layer 0 is [-5, 5) mm, so z = 4 mm stays in it, while x and y
  // from 0 to 10 cm now touch 11 voxels each.
  const Eigen::Vector3d origin(-0.005, -0.005, -0.005);
  const VoxelOverlap overlap = CompareWithSurface(Sheet(), {}, origin, kVoxel);
  EXPECT_EQ(overlap.truth, 121u);
  EXPECT_EQ(overlap.Iou(), 0.0);
}

TEST(VoxelOverlap, ComparesTwoSetsOfCentres) {
  const std::vector<Eigen::Vector3f> truth = {Centre(0, 0, 0), Centre(1, 0, 0), Centre(2, 0, 0)};
  const std::vector<Eigen::Vector3f> proxy = {Centre(1, 0, 0), Centre(2, 0, 0), Centre(2, 0, 0),
                                              Centre(3, 0, 0)};
  const VoxelOverlap overlap = CompareVoxelSets(truth, proxy, Eigen::Vector3d::Zero(), kVoxel);
  EXPECT_EQ(overlap.truth, 3u);
  EXPECT_EQ(overlap.proxy, 3u);  // a repeated centre counts once
  EXPECT_EQ(overlap.both, 2u);
  EXPECT_NEAR(overlap.Iou(), 0.5, 1e-12);
}

TEST(VoxelOverlap, RefusesCentresOffTheGridAndBadSizes) {
  EXPECT_THROW(CompareWithSurface(Sheet(), {Eigen::Vector3f(0.001f, 0.005f, 0.005f)},
                                  Eigen::Vector3d::Zero(), kVoxel),
               std::invalid_argument);
  EXPECT_THROW(CompareWithSurface(Sheet(), {}, Eigen::Vector3d::Zero(), 0), std::invalid_argument);
}

}  // namespace
}  // namespace avc::eval
