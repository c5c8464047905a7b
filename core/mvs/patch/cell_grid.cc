#include "core/mvs/patch/cell_grid.h"

#include <algorithm>
#include <cmath>

namespace avc::mvs::patch {

CellGrids::CellGrids(const std::vector<PatchImage>& images, int cell_size) : cell_size_(cell_size) {
  grids_.resize(images.size());
  for (size_t i = 0; i < images.size(); ++i) {
    Grid& g = grids_[i];
    g.cols = (images[i].width() + cell_size - 1) / cell_size;
    g.rows = (images[i].height() + cell_size - 1) / cell_size;
    g.ids.resize(static_cast<size_t>(g.cols) * g.rows);
    g.nearest.assign(g.ids.size(), std::numeric_limits<float>::infinity());
  }
}

bool CellGrids::CellOf(size_t image, double u, double v, int* cx, int* cy) const {
  // Pixel centres are at integers: pixel x covers [x - 0.5, x + 0.5).
  const double fu = std::floor((u + 0.5) / cell_size_);
  const double fv = std::floor((v + 0.5) / cell_size_);
  const Grid& g = grids_[image];
  if (!(fu >= 0 && fv >= 0 && fu < g.cols && fv < g.rows)) return false;
  *cx = static_cast<int>(fu);
  *cy = static_cast<int>(fv);
  return true;
}

bool CellGrids::CellOfPoint(size_t image, const PatchImage& view, const Eigen::Vector3d& point,
                            int* cx, int* cy, double* depth) const {
  const Eigen::Vector3d h = view.ProjectH(point);
  if (depth != nullptr) *depth = h.z();
  return CellOf(image, h.x() / h.z(), h.y() / h.z(), cx, cy);
}

void CellGrids::Add(uint32_t id, const Patch& patch, const std::vector<PatchImage>& images) {
  for (uint32_t j : patch.visible) {
    const Eigen::Vector3d h = images[j].ProjectH(patch.centre);
    if (h.z() <= 0) continue;
    int cx = 0, cy = 0;
    if (!CellOf(j, h.x() / h.z(), h.y() / h.z(), &cx, &cy)) continue;
    Grid& g = grids_[j];
    const size_t cell = static_cast<size_t>(cy) * g.cols + cx;
    g.ids[cell].push_back(id);
    g.nearest[cell] = std::min(g.nearest[cell], static_cast<float>(h.z()));
  }
}

void CellGrids::Rebuild(const std::vector<Patch>& patches, const std::vector<uint8_t>& alive,
                        const std::vector<PatchImage>& images) {
  for (Grid& g : grids_) {
    for (auto& ids : g.ids) ids.clear();
    std::fill(g.nearest.begin(), g.nearest.end(), std::numeric_limits<float>::infinity());
  }
  for (size_t id = 0; id < patches.size(); ++id) {
    if (alive[id]) Add(static_cast<uint32_t>(id), patches[id], images);
  }
}

}  // namespace avc::mvs::patch
