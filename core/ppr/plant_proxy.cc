#include "core/ppr/plant_proxy.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "core/ppr/octree_binary.h"
#include "core/ppr/proxy_octree.h"

namespace avc::ppr {
namespace {

constexpr int kMaxTopLevel = kOctreeDepth - 1;  // a tile must be below OctoMap's root

void CheckKeyRange(const Eigen::Array3i& begin, const Eigen::Array3i& end, double voxel_size) {
  if ((begin < -kOctreeKeyOffset).any() || (end > kOctreeKeyOffset).any()) {
    throw std::invalid_argument(fmt::format(
        "PlantProxy: at voxel size {} m the box lies outside OctoMap's 16-bit key range "
        "(|coordinate| < {} m)",
        voxel_size, voxel_size * kOctreeKeyOffset));
  }
}

// Appends `cell` and merges runs of eight equal siblings into their parent, so the cells stay
// the coarsest description of the votes.
void PushMerging(std::vector<ProxyCell>& cells, const ProxyCell& cell, int top_level) {
  cells.push_back(cell);
  while (cells.size() >= 8) {
    const ProxyCell last = cells.back();
    if (last.level >= top_level || ChildIndex(last) != 7) return;
    const auto first = cells.end() - 8;
    for (int i = 0; i < 8; ++i) {
      const ProxyCell& c = first[i];
      if (c.level != last.level || ChildIndex(c) != i || (c.x >> 1) != (last.x >> 1) ||
          (c.y >> 1) != (last.y >> 1) || (c.z >> 1) != (last.z >> 1) ||
          c.background_votes != last.background_votes || c.plant_votes != last.plant_votes) {
        return;
      }
    }
    ProxyCell parent = last;
    parent.level += 1;
    parent.x >>= 1;
    parent.y >>= 1;
    parent.z >>= 1;
    cells.erase(first, cells.end());
    cells.push_back(parent);
  }
}

void CarveCell(const FootprintTest& test, ProxyCell cell, int allowed,
               std::vector<ProxyCell>& out) {
  switch (test.Classify(cell)) {
    case Footprint::kNoVote:
      break;
    case Footprint::kBackground:
      if (++cell.background_votes > allowed) return;  // free: carved away
      break;
    case Footprint::kPlant:
      if (cell.plant_votes < std::numeric_limits<uint16_t>::max()) ++cell.plant_votes;
      break;
    case Footprint::kMixed:
      for (int i = 0; i < 8; ++i) CarveCell(test, ChildCell(cell, i), allowed, out);
      return;
  }
  out.push_back(cell);
}

// Cells of the tiling that lie inside [begin, end), split where a tile leaves the box.
void TileInside(const ProxyCell& cell, const Eigen::Array3i& begin, const Eigen::Array3i& end,
                std::vector<ProxyCell>& out) {
  const Eigen::Array3i lo = Eigen::Array3i(cell.x, cell.y, cell.z) * (1 << cell.level);
  const Eigen::Array3i hi = lo + (1 << cell.level);
  if ((hi <= begin).any() || (lo >= end).any()) return;
  if ((lo >= begin).all() && (hi <= end).all()) {
    out.push_back(cell);
    return;
  }
  for (int i = 0; i < 8; ++i) TileInside(ChildCell(cell, i), begin, end, out);
}

uint64_t VoxelsIn(const ProxyCell& cell) { return uint64_t{1} << (3 * cell.level); }

}  // namespace

PlantProxy::PlantProxy(const Eigen::AlignedBox3d& box, const ProxyOptions& options)
    : options_(options) {
  if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite() ||
      !(box.sizes().array() > 0).all()) {
    throw std::invalid_argument("PlantProxy: the box must be finite with positive size");
  }
  if (options.background_votes_allowed < 0 || options.background_votes_allowed > 1000) {
    throw std::invalid_argument("PlantProxy: background_votes_allowed must be in [0, 1000]");
  }
  if (options.min_plant_views < 0) {
    throw std::invalid_argument("PlantProxy: min_plant_views must be 0 (automatic) or more");
  }
  if (!std::isfinite(options.final_voxel_size) || options.final_voxel_size < 0) {
    throw std::invalid_argument("PlantProxy: final_voxel_size must be 0 (automatic) or positive");
  }
  if (options.resolution_increases < 0 || options.resolution_increases > 8) {
    throw std::invalid_argument("PlantProxy: resolution_increases must be in [0, 8]");
  }
  if (options.coarse_levels < 0 || options.coarse_levels > kMaxTopLevel) {
    throw std::invalid_argument(
        fmt::format("PlantProxy: coarse_levels must be in [0, {}]", kMaxTopLevel));
  }
  if (options_.final_voxel_size == 0) options_.final_voxel_size = box.sizes().maxCoeff() / 256;
  voxel_size_ = std::ldexp(options_.final_voxel_size, options_.resolution_increases);

  // Voxel index range, rounded outwards to whole blocks of 8 voxels (fewer fine free octree
  // nodes along the box faces).
  const Eigen::Array3d lo = (box.min().array() / voxel_size_).floor();
  const Eigen::Array3d hi = (box.max().array() / voxel_size_).ceil();
  if ((lo < -kOctreeKeyOffset).any() || (hi > kOctreeKeyOffset).any()) {
    CheckKeyRange(Eigen::Array3i::Constant(-kOctreeKeyOffset - 1), Eigen::Array3i::Zero(),
                  voxel_size_);
  }
  const int extent = static_cast<int>((hi - lo).maxCoeff());
  top_level_ = options_.coarse_levels;
  if (top_level_ == 0) {
    while (top_level_ < kMaxTopLevel && (4 << top_level_) <= extent) ++top_level_;
  }
  const double block = 1 << std::min(top_level_, 3);
  box_begin_ = ((lo / block).floor() * block).cast<int>();
  box_end_ = ((hi / block).ceil() * block).cast<int>();
  CheckKeyRange(box_begin_, box_end_, voxel_size_);

  ForEachTopCell(box_begin_, box_end_, top_level_, [&](int tx, int ty, int tz) {
    TileInside(ProxyCell{tx, ty, tz, top_level_, 0, 0}, box_begin_, box_end_, cells_);
  });
}

PlantProxy::~PlantProxy() = default;
PlantProxy::PlantProxy(PlantProxy&&) noexcept = default;
PlantProxy& PlantProxy::operator=(PlantProxy&&) noexcept = default;

void PlantProxy::AddView(const camera::Camera& camera, const cv::Mat& mask,
                         const std::string& name) {
  const std::string label = name.empty() ? fmt::format("#{}", views_.size()) : name;
  if (views_released_) {
    throw std::logic_error("PlantProxy::AddView: the views were released (ReleaseViews)");
  }
  views_.push_back(PrepareCarvingView(camera, mask, label));
  Carve(views_.back());
}

void PlantProxy::Carve(const CarvingView& view) {
  const FootprintTest test(view, voxel_size_);
  // Fixed blocks, each carved in order into its own output: the result does not depend on
  // which thread ran which block.
  constexpr size_t kBlock = 256;
  const size_t blocks = (cells_.size() + kBlock - 1) / kBlock;
  std::vector<std::vector<ProxyCell>> carved(blocks);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks), [&](const auto& range) {
    for (size_t b = range.begin(); b != range.end(); ++b) {
      const size_t end = std::min(cells_.size(), (b + 1) * kBlock);
      for (size_t i = b * kBlock; i < end; ++i) {
        CarveCell(test, cells_[i], options_.background_votes_allowed, carved[b]);
      }
    }
  });
  std::vector<ProxyCell> merged;
  merged.reserve(cells_.size());
  for (const auto& block : carved) {
    for (const ProxyCell& cell : block) PushMerging(merged, cell, top_level_);
  }
  cells_ = std::move(merged);
  tree_.reset();
}

void PlantProxy::ReleaseViews() {
  views_released_ = true;
  view_count_ = static_cast<int>(views_.size());
  views_ = {};
}

void PlantProxy::IncreaseResolution() {
  if (views_released_) {
    throw std::logic_error("PlantProxy::IncreaseResolution: the views were released");
  }
  if (top_level_ + 1 > kMaxTopLevel) {
    throw std::runtime_error("PlantProxy::IncreaseResolution: octree depth exhausted");
  }
  CheckKeyRange(box_begin_ * 2, box_end_ * 2, voxel_size_ / 2);
  voxel_size_ /= 2;
  box_begin_ *= 2;
  box_end_ *= 2;
  ++top_level_;
  // Same cubes, one level higher in the finer grid; votes are recounted from scratch since a
  // child can see fewer plant pixels than its parent did.
  for (ProxyCell& cell : cells_) {
    cell.level += 1;
    cell.background_votes = 0;
    cell.plant_votes = 0;
  }
  for (const CarvingView& view : views_) Carve(view);
  tree_.reset();
}

Eigen::AlignedBox3d PlantProxy::box() const {
  return {box_begin_.cast<double>().matrix() * voxel_size_,
          box_end_.cast<double>().matrix() * voxel_size_};
}

VoxelState PlantProxy::CellState(const ProxyCell& cell) const {
  if (cell.background_votes > options_.background_votes_allowed) return VoxelState::kFree;
  return cell.plant_votes >= MinPlantViews() ? VoxelState::kOccupied : VoxelState::kUnknown;
}

int PlantProxy::MinPlantViews() const {
  if (options_.min_plant_views > 0) return options_.min_plant_views;
  return std::max(2, (view_count() + 1) / 2);
}

VoxelState PlantProxy::State(const Eigen::Vector3d& point) const {
  if (!point.allFinite()) return VoxelState::kUnknown;
  const octomap::OcTree& octree = tree();
  const octomap::OcTreeNode* node = octree.search(point.x(), point.y(), point.z());
  if (node == nullptr) return VoxelState::kUnknown;
  return octree.isNodeOccupied(node) ? VoxelState::kOccupied : VoxelState::kFree;
}

VoxelCounts PlantProxy::Counts() const {
  const Eigen::Array<uint64_t, 3, 1> extent = (box_end_ - box_begin_).cast<uint64_t>();
  VoxelCounts counts;
  uint64_t live = 0;
  for (const ProxyCell& cell : cells_) {
    const uint64_t voxels = VoxelsIn(cell);
    live += voxels;
    (CellState(cell) == VoxelState::kOccupied ? counts.occupied : counts.unknown) += voxels;
  }
  counts.free = extent.prod() - live;
  return counts;
}

std::vector<Eigen::Vector3f> PlantProxy::OccupiedCentres() const {
  std::vector<std::tuple<int, int, int>> voxels;  // (z, y, x): sorts in the documented order
  for (const ProxyCell& cell : cells_) {
    if (CellState(cell) != VoxelState::kOccupied) continue;
    const int n = 1 << cell.level;
    for (int z = cell.z * n; z < (cell.z + 1) * n; ++z) {
      for (int y = cell.y * n; y < (cell.y + 1) * n; ++y) {
        for (int x = cell.x * n; x < (cell.x + 1) * n; ++x) voxels.emplace_back(z, y, x);
      }
    }
  }
  std::sort(voxels.begin(), voxels.end());
  std::vector<Eigen::Vector3f> centres;
  centres.reserve(voxels.size());
  for (const auto& [z, y, x] : voxels) {
    centres.emplace_back(static_cast<float>((x + 0.5) * voxel_size_),
                         static_cast<float>((y + 0.5) * voxel_size_),
                         static_cast<float>((z + 0.5) * voxel_size_));
  }
  return centres;
}

Eigen::AlignedBox3d PlantProxy::OccupiedBounds() const {
  Eigen::AlignedBox3d bounds;  // empty
  for (const ProxyCell& cell : cells_) {
    if (CellState(cell) != VoxelState::kOccupied) continue;
    const Eigen::Vector3d lo = Eigen::Vector3d(cell.x, cell.y, cell.z) *
                               (voxel_size_ * static_cast<double>(1 << cell.level));
    bounds.extend(lo);
    bounds.extend(lo + Eigen::Vector3d::Constant(voxel_size_ * (1 << cell.level)));
  }
  return bounds;
}

mvs::MvsBounds PlantProxy::ToMvsBounds() const { return {OccupiedCentres(), voxel_size_}; }

const octomap::OcTree& PlantProxy::tree() const {
  if (!tree_) {
    std::vector<VoxelState> states;
    states.reserve(cells_.size());
    for (const ProxyCell& cell : cells_) states.push_back(CellState(cell));
    tree_ = BuildProxyOctree({&cells_, &states, box_begin_, box_end_, top_level_, voxel_size_});
  }
  return *tree_;
}

std::string PlantProxy::BinaryBytes() const { return OctreeBinaryBytes(tree()); }

void PlantProxy::WriteBinary(const std::filesystem::path& path) const {
  const std::string bytes = BinaryBytes();
  std::ofstream file(path, std::ios::binary);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!file) throw std::runtime_error(fmt::format("{}: cannot write the octree", path.string()));
}

}  // namespace avc::ppr
