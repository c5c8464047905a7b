#include "core/merge/merge_points.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <unordered_set>

namespace avc::merge {
namespace {

// (z, y, x): sorts voxels in the documented order.
using Key = std::tuple<int, int, int>;

Key KeyOf(const Eigen::Vector3d& cell) {
  return {static_cast<int>(std::floor(cell.z())), static_cast<int>(std::floor(cell.y())),
          static_cast<int>(std::floor(cell.x()))};
}

struct KeyHash {
  size_t operator()(const Key& key) const {
    const auto [z, y, x] = key;
    return (static_cast<size_t>(static_cast<uint32_t>(z)) * 73856093u) ^
           (static_cast<size_t>(static_cast<uint32_t>(y)) * 19349663u) ^
           (static_cast<size_t>(static_cast<uint32_t>(x)) * 83492791u);
  }
};

struct Accumulator {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  Eigen::Vector3d colour = Eigen::Vector3d::Zero();
  double confidence = 0;
  uint32_t count = 0;
};

void CheckVoxelSize(const mvs::MvsBounds& proxy, const char* who) {
  if (!(std::isfinite(proxy.voxel_size) && proxy.voxel_size > 0)) {
    throw std::invalid_argument(
        fmt::format("{}: voxel size {} must be positive", who, proxy.voxel_size));
  }
}

std::unordered_set<Key, KeyHash> OccupiedKeys(const mvs::MvsBounds& proxy) {
  std::unordered_set<Key, KeyHash> keys;
  keys.reserve(proxy.occupied_centres.size());
  for (size_t i = 0; i < proxy.occupied_centres.size(); ++i) {
    const Eigen::Vector3d cell = proxy.occupied_centres[i].cast<double>() / proxy.voxel_size;
    const Eigen::Vector3d offset = cell.array() - cell.array().floor() - 0.5;
    if (!cell.allFinite() || offset.cwiseAbs().maxCoeff() > 0.1) {
      throw std::invalid_argument(
          fmt::format("occupied centre {} is not a voxel centre of the proxy's grid", i));
    }
    keys.insert(KeyOf(cell));
  }
  return keys;
}

}  // namespace

mvs::MvsPoints PointsInProxy(const mvs::MvsPoints& points, const mvs::MvsBounds& proxy,
                             int margin_voxels, uint64_t* removed) {
  CheckVoxelSize(proxy, "PointsInProxy");
  if (margin_voxels < 0) throw std::invalid_argument("PointsInProxy: negative margin");
  std::unordered_set<Key, KeyHash> near = OccupiedKeys(proxy);
  if (margin_voxels > 0) {
    const std::vector<Key> occupied(near.begin(), near.end());
    const int m = margin_voxels;
    for (const auto& [z, y, x] : occupied) {
      for (int dz = -m; dz <= m; ++dz) {
        for (int dy = -m; dy <= m; ++dy) {
          for (int dx = -m; dx <= m; ++dx) near.insert({z + dz, y + dy, x + dx});
        }
      }
    }
  }
  mvs::MvsPoints kept;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!near.contains(KeyOf(points.cloud.positions[i].cast<double>() / proxy.voxel_size))) {
      continue;
    }
    kept.cloud.positions.push_back(points.cloud.positions[i]);
    kept.cloud.normals.push_back(points.cloud.normals[i]);
    kept.cloud.colors.push_back(points.cloud.colors[i]);
    kept.confidence.push_back(points.confidence[i]);
    kept.views.push_back(points.views[i]);
  }
  if (removed != nullptr) *removed = points.size() - kept.size();
  return kept;
}

MergedPoints MergeIntoProxy(const mvs::MvsPoints& points, const mvs::MvsBounds& proxy,
                            const MergeOptions& options) {
  CheckVoxelSize(proxy, "MergeIntoProxy");
  if (options.min_points < 1) {
    throw std::invalid_argument("MergeIntoProxy: min_points must be at least 1");
  }
  if (const std::string problem = points.Validate(); !problem.empty()) {
    throw std::invalid_argument("MergeIntoProxy: " + problem);
  }
  const std::unordered_set<Key, KeyHash> occupied = OccupiedKeys(proxy);

  MergedPoints merged;
  merged.voxel_size = proxy.voxel_size;
  // Sums in point order per voxel, voxels in key order: the same bytes on any machine.
  std::map<Key, Accumulator> voxels;
  for (size_t i = 0; i < points.size(); ++i) {
    const Key key = KeyOf(points.cloud.positions[i].cast<double>() / proxy.voxel_size);
    if (!occupied.contains(key)) {
      ++merged.outside_proxy;
      continue;
    }
    Accumulator& sum = voxels[key];
    sum.position += points.cloud.positions[i].cast<double>();
    sum.normal += points.cloud.normals[i].cast<double>();
    sum.colour += points.cloud.colors[i].cast<double>();
    sum.confidence += points.confidence[i];
    ++sum.count;
  }
  for (const auto& [key, sum] : voxels) {
    if (sum.count < static_cast<uint32_t>(options.min_points)) {
      merged.in_sparse_voxels += sum.count;
      continue;
    }
    const double n = sum.count;
    const auto [z, y, x] = key;
    merged.cloud.positions.push_back((sum.position / n).cast<float>());
    const double length = sum.normal.norm();
    // Opposite normals cancelling exactly leave no direction: +z stands in.
    const Eigen::Vector3d normal =
        length > 0 ? Eigen::Vector3d(sum.normal / length) : Eigen::Vector3d::UnitZ();
    merged.cloud.normals.push_back(normal.cast<float>());
    merged.cloud.colors.push_back(
        (sum.colour / n).array().round().min(255).max(0).cast<uint8_t>().matrix());
    merged.confidence.push_back(static_cast<float>(sum.confidence / n));
    merged.point_counts.push_back(sum.count);
    merged.voxels.emplace_back(x, y, z);
  }
  return merged;
}

}  // namespace avc::merge
