#pragma once

// Model merging (paper §3.1): multi-view stereo points pooled in the plant proxy's voxels. A
// voxel of the proxy's grid that is occupied and holds more than `min_points - 1` points is part
// of the plant, and its points become one averaged point; points in other voxels are outliers.
// The voxel index of each merged point is kept: face- or corner-adjacent voxels are the
// connectivity the clusterer and surfacer use.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/geometry/point_cloud.h"
#include "core/mvs/mvs_bounds.h"
#include "core/mvs/mvs_points.h"

namespace avc::merge {

struct MergeOptions {
  // The paper keeps a voxel holding "more than 3" points.
  int min_points = 4;
};

struct MergedPoints {
  // One point per kept voxel, sorted by voxel index (z, then y, then x): the mean position, the
  // normalised sum of normals, the mean colour.
  geometry::PointCloud cloud;
  std::vector<float> confidence;        // mean confidence of the voxel's points
  std::vector<uint32_t> point_counts;   // MVS points merged into each
  std::vector<Eigen::Vector3i> voxels;  // voxel index: [i, i + 1) * voxel_size per axis
  double voxel_size = 0;
  uint64_t outside_proxy = 0;     // points in voxels the proxy does not call occupied
  uint64_t in_sparse_voxels = 0;  // points in occupied voxels with too few points

  size_t size() const { return cloud.size(); }
};

// `proxy`'s occupied centres must be voxel centres of the grid whose voxel i spans
// [i, i + 1) * voxel_size (the plant proxy's own grid). Throws std::invalid_argument naming the
// problem for a bad voxel size, an off-grid centre, inconsistent points or min_points < 1.
MergedPoints MergeIntoProxy(const mvs::MvsPoints& points, const mvs::MvsBounds& proxy,
                            const MergeOptions& options = {});

// The points that lie in the proxy's occupied voxels or within `margin_voxels` voxels of one
// (26-neighbourhood steps), in their order; `removed` (optional) gets how many did not.
// Multi-view stereo is bounded by the proxy, but patch expansion reaches past it (on a real
// scan, 19 % of the points: the stage under the plant). Same contract as MergeIntoProxy for the
// proxy; throws std::invalid_argument for a negative margin.
mvs::MvsPoints PointsInProxy(const mvs::MvsPoints& points, const mvs::MvsBounds& proxy,
                             int margin_voxels, uint64_t* removed = nullptr);

}  // namespace avc::merge
