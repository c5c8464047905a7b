#pragma once

// How well a set of occupied voxels (a carved plant proxy) matches a ground-truth surface
// voxelised on the same grid: intersection over union, and the two one-sided fractions.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/geometry/mesh.h"

namespace avc::eval {

struct VoxelOverlap {
  uint64_t truth = 0;  // voxels the ground-truth surface passes through
  uint64_t proxy = 0;  // occupied voxels given
  uint64_t both = 0;   // in both sets

  double Iou() const;        // both / (truth + proxy - both); 0 when both sets are empty
  double Precision() const;  // both / proxy: occupied voxels the surface is in
  double Recall() const;     // both / truth: surface voxels kept occupied
};

// Voxel (i, j, k) of the grid is [origin + size * (i, j, k), origin + size * (i + 1, j + 1,
// k + 1)); `occupied_centres` are the centres of occupied voxels of that grid. The surface is
// voxelised from area-uniform samples, 16 per voxel face area (at most a sliver of a voxel the
// surface merely grazes is missed). Throws std::invalid_argument for a non-positive voxel size
// or a centre off the grid by more than a tenth of a voxel.
// Two sets of voxel centres on one grid (as above): `truth` plays the ground truth.
VoxelOverlap CompareVoxelSets(const std::vector<Eigen::Vector3f>& truth_centres,
                              const std::vector<Eigen::Vector3f>& occupied_centres,
                              const Eigen::Vector3d& origin, double voxel_size);

VoxelOverlap CompareWithSurface(const geometry::Mesh& truth,
                                const std::vector<Eigen::Vector3f>& occupied_centres,
                                const Eigen::Vector3d& origin, double voxel_size,
                                uint64_t seed = 1);

}  // namespace avc::eval
