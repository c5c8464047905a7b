#include "services/planner/proxy_patches.h"

#include <algorithm>
#include <array>
#include <map>
#include <tuple>

namespace avc::planner {
namespace {

constexpr std::array<std::array<int, 3>, 6> kFaces = {
    {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};

}  // namespace

std::vector<SurfacePatch> ProxySurfacePatches(const ppr::PlantProxy& proxy,
                                              const PatchOptions& options) {
  const Eigen::AlignedBox3d box = proxy.OccupiedBounds();
  if (box.isEmpty()) return {};
  const double voxel = proxy.voxel_size();
  const double cell = std::max(box.sizes().maxCoeff() / std::max(1, options.cells_across), voxel);

  // (cell x, y, z, direction) -> patch; std::map keeps the order deterministic.
  std::map<std::tuple<int, int, int, int>, SurfacePatch> patches;
  for (const Eigen::Vector3f& c : proxy.OccupiedCentres()) {
    const Eigen::Vector3d centre = c.cast<double>();
    const Eigen::Vector3i index =
        ((centre - box.min()) / cell).array().floor().cast<int>().matrix();
    for (int direction = 0; direction < 6; ++direction) {
      const auto& face = kFaces[direction];
      const Eigen::Vector3d step(face[0], face[1], face[2]);
      const ppr::VoxelState state = proxy.State(centre + voxel * step);
      if (state == ppr::VoxelState::kOccupied) continue;
      SurfacePatch& patch = patches[{index.x(), index.y(), index.z(), direction}];
      patch.normal = step;
      patch.points.push_back(centre + 0.5 * voxel * step);
      patch.unknown_faces += state == ppr::VoxelState::kUnknown;
    }
  }

  std::vector<SurfacePatch> result;
  for (auto& [key, patch] : patches) {
    if (static_cast<int>(patch.points.size()) < options.min_faces) continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : patch.points) sum += p;
    patch.centre = sum / static_cast<double>(patch.points.size());
    result.push_back(std::move(patch));
  }
  return result;
}

}  // namespace avc::planner
