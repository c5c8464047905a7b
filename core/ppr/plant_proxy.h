#pragma once

// The plant proxy representation (PPR, paper §2.2 and Algorithm 1): tolerant projection carving
// of plant masks into a voxel grid over a box, coarse to fine, with each voxel occupied, free or
// unknown, mirrored in an OctoMap OcTree for the planner (ray casts) and exported as .bt.
//
// Voting: each view votes on each voxel through the voxel's projected footprint (the bounding
// rectangle of its 8 projected corners):
//  - background vote: every footprint pixel is background;
//  - plant vote: at least one footprint pixel is plant;
//  - no vote: the voxel is behind the camera, its footprint leaves the image (and shows no
//    plant), or its pixels map outside the real image after undistortion.
// State of a voxel after the views so far:
//  - free:     background votes > k (`background_votes_allowed`), so a leaf lost in k masks
//              survives;
//  - occupied: not free and plant votes >= m (`min_plant_views`, by default half the views);
//  - unknown:  otherwise (seen too little), and everything outside the box.
// Voxel states, counts and the octree do not depend on the order of the views.
//
// Coarse to fine: the box is covered by octree-aligned cells that are only split where a view's
// verdict differs inside them, and dropped as soon as they are free, so empty space costs little.
// The octree has resolution = voxel size; occupied voxels are occupied nodes, free voxels free
// nodes (pruned into large cells), unknown voxels absent.

#include <octomap/OcTree.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/dataset/view.h"
#include "core/mvs/mvs_bounds.h"
#include "core/ppr/carving_view.h"
#include "core/ppr/proxy_cell.h"

namespace avc::ppr {

struct ProxyOptions {
  // k: background votes a voxel survives. 1 keeps the Middlebury dino's shape with 16 views
  // while a leaf erased from one mask survives (see tests/ppr).
  int background_votes_allowed = 1;
  // m: plant votes needed to call a voxel occupied; 0 = automatic: half the views so far, at
  // least 2 (one view only fixes a ray, and cones of a few views also cross far from the
  // object, where most views do not see).
  int min_plant_views = 0;
  // Voxel edge after all resolution increases, metres; 0 = longest box edge / 256.
  double final_voxel_size = 0;
  // Algorithm 1 line 25: the proxy starts at final_voxel_size * 2^n and each
  // IncreaseResolution() halves the voxel size.
  int resolution_increases = 1;
  // Levels of cells above a voxel used to prune empty space; 0 = automatic (top cells about a
  // quarter of the box's longest edge).
  int coarse_levels = 0;
};

struct VoxelCounts {
  uint64_t occupied = 0;
  uint64_t free = 0;
  uint64_t unknown = 0;  // inside the box
};

class PlantProxy {
 public:
  // Throws std::invalid_argument for an empty or non-finite box or bad options.
  explicit PlantProxy(const Eigen::AlignedBox3d& box, const ProxyOptions& options = {});
  ~PlantProxy();
  PlantProxy(PlantProxy&&) noexcept;
  PlantProxy& operator=(PlantProxy&&) noexcept;

  // Carves with one more view and keeps it for later resolution increases. Throws
  // std::invalid_argument naming the view (or "view #i") for a bad camera or mask.
  void AddView(const camera::Camera& camera, const cv::Mat& mask, const std::string& name = {});
  void AddView(const dataset::View& view) { AddView(view.camera, view.mask, view.name); }

  // Halves the voxel size and re-carves the children of every voxel not yet free against all
  // views so far; space already free stays free.
  void IncreaseResolution();

  double voxel_size() const { return voxel_size_; }
  // The box the voxels cover: the constructor's box rounded outwards to whole voxels.
  Eigen::AlignedBox3d box() const;
  int view_count() const { return views_released_ ? view_count_ : static_cast<int>(views_.size()); }
  // Frees the views' carving data once no view will be added and the resolution is final (a
  // 72-view real scan's masks are 126 MB); AddView and IncreaseResolution then throw.
  void ReleaseViews();
  const ProxyOptions& options() const { return options_; }

  VoxelState State(const Eigen::Vector3d& point) const;
  VoxelCounts Counts() const;
  // Centres of occupied voxels, sorted by voxel index (z, then y, then x).
  std::vector<Eigen::Vector3f> OccupiedCentres() const;
  // Bounding box of the occupied voxels (whole voxels); empty when none is occupied.
  Eigen::AlignedBox3d OccupiedBounds() const;
  mvs::MvsBounds ToMvsBounds() const;

  // The octree, current with every view added. Built on demand: not safe to call from two
  // threads at once.
  const octomap::OcTree& tree() const;
  // OctoMap's binary .bt format (max-likelihood occupied/free), as octovis reads it.
  std::string BinaryBytes() const;
  void WriteBinary(const std::filesystem::path& path) const;

 private:
  void Carve(const CarvingView& view);
  VoxelState CellState(const ProxyCell& cell) const;
  int MinPlantViews() const;

  ProxyOptions options_;
  double voxel_size_ = 0;
  int top_level_ = 0;                   // level of the cells the box is tiled with
  Eigen::Array3i box_begin_, box_end_;  // voxel index range [begin, end) covered
  std::vector<ProxyCell> cells_;        // not-free space, octree depth-first order
  std::vector<CarvingView> views_;
  bool views_released_ = false;
  int view_count_ = 0;                             // once released
  mutable std::unique_ptr<octomap::OcTree> tree_;  // null when stale
};

}  // namespace avc::ppr
