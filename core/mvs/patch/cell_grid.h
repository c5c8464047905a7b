#pragma once

// Per image, the β x β pixel cells and the patches that project into each (for the images in
// their V*), with the nearest such patch's depth: what expansion looks for (empty cells) and
// what the visibility tests compare depths against.

#include <cstdint>
#include <limits>
#include <vector>

#include "core/mvs/patch/patch.h"
#include "core/mvs/patch/patch_image.h"

namespace avc::mvs::patch {

class CellGrids {
 public:
  CellGrids(const std::vector<PatchImage>& images, int cell_size);

  int cell_size() const { return cell_size_; }
  int cols(size_t image) const { return grids_[image].cols; }
  int rows(size_t image) const { return grids_[image].rows; }
  // The cell of pixel (u, v) in image; false when outside the grid.
  bool CellOf(size_t image, double u, double v, int* cx, int* cy) const;
  // The cell world point `point` projects to in `view` (image `image`), and its depth there.
  // The point must lie in front of the camera.
  bool CellOfPoint(size_t image, const PatchImage& view, const Eigen::Vector3d& point, int* cx,
                   int* cy, double* depth = nullptr) const;
  // How far (metres, along the ray) a patch at `depth` may lie behind another before it counts
  // as hidden: `cells` cell footprints at that depth.
  double OcclusionTolerance(double cells, double depth, double fx) const {
    return cells * cell_size_ * depth / fx;
  }

  // Registers patch `id` in the cell of its centre in every image of its V*.
  void Add(uint32_t id, const Patch& patch, const std::vector<PatchImage>& images);
  // Forgets every patch and registers the alive ones again in id order.
  void Rebuild(const std::vector<Patch>& patches, const std::vector<uint8_t>& alive,
               const std::vector<PatchImage>& images);

  const std::vector<uint32_t>& Patches(size_t image, int cx, int cy) const {
    const Grid& g = grids_[image];
    return g.ids[static_cast<size_t>(cy) * g.cols + cx];
  }
  bool Empty(size_t image, int cx, int cy) const { return Patches(image, cx, cy).empty(); }
  // Depth of the nearest registered patch; +inf when the cell is empty.
  float NearestDepth(size_t image, int cx, int cy) const {
    const Grid& g = grids_[image];
    return g.nearest[static_cast<size_t>(cy) * g.cols + cx];
  }

 private:
  struct Grid {
    int cols = 0, rows = 0;
    std::vector<std::vector<uint32_t>> ids;
    std::vector<float> nearest;
  };
  int cell_size_;
  std::vector<Grid> grids_;
};

}  // namespace avc::mvs::patch
