#include "core/eval/voxel_overlap.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "core/eval/surface_sampling.h"

namespace avc::eval {
namespace {

using Key = Eigen::Matrix<int64_t, 3, 1>;

// One 64-bit code per voxel (21 bits per axis, offset to be positive), for sorting.
uint64_t Code(const Key& key) {
  constexpr int64_t kOffset = int64_t{1} << 20;
  uint64_t code = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int64_t shifted = key[axis] + kOffset;
    if (shifted < 0 || shifted >= 2 * kOffset) {
      throw std::invalid_argument("CompareWithSurface: the grid spans more than 2^21 voxels");
    }
    code = (code << 21) | static_cast<uint64_t>(shifted);
  }
  return code;
}

std::vector<uint64_t> SortedUnique(std::vector<uint64_t> codes) {
  std::sort(codes.begin(), codes.end());
  codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
  return codes;
}

void CheckVoxelSize(double voxel_size) {
  if (!(std::isfinite(voxel_size) && voxel_size > 0)) {
    throw std::invalid_argument(
        fmt::format("voxel overlap: voxel size {} must be positive", voxel_size));
  }
}

std::vector<uint64_t> CentreCodes(const std::vector<Eigen::Vector3f>& centres,
                                  const Eigen::Vector3d& origin, double voxel_size) {
  std::vector<uint64_t> codes;
  codes.reserve(centres.size());
  for (size_t i = 0; i < centres.size(); ++i) {
    const Eigen::Vector3d cell = (centres[i].cast<double>() - origin) / voxel_size;
    const Eigen::Vector3d rounded = (cell.array() - 0.5).round();
    if (!cell.allFinite() || ((cell.array() - 0.5) - rounded.array()).abs().maxCoeff() > 0.1) {
      throw std::invalid_argument(
          fmt::format("voxel overlap: centre {} is not a voxel centre of the grid", i));
    }
    codes.push_back(Code(rounded.cast<int64_t>()));
  }
  return SortedUnique(std::move(codes));
}

VoxelOverlap Overlap(const std::vector<uint64_t>& truth, const std::vector<uint64_t>& proxy) {
  VoxelOverlap overlap;
  overlap.truth = truth.size();
  overlap.proxy = proxy.size();
  std::vector<uint64_t> common;
  std::set_intersection(truth.begin(), truth.end(), proxy.begin(), proxy.end(),
                        std::back_inserter(common));
  overlap.both = common.size();
  return overlap;
}

}  // namespace

double VoxelOverlap::Iou() const {
  const uint64_t either = truth + proxy - both;
  return either == 0 ? 0.0 : static_cast<double>(both) / static_cast<double>(either);
}

double VoxelOverlap::Precision() const {
  return proxy == 0 ? 0.0 : static_cast<double>(both) / static_cast<double>(proxy);
}

double VoxelOverlap::Recall() const {
  return truth == 0 ? 0.0 : static_cast<double>(both) / static_cast<double>(truth);
}

VoxelOverlap CompareVoxelSets(const std::vector<Eigen::Vector3f>& truth_centres,
                              const std::vector<Eigen::Vector3f>& occupied_centres,
                              const Eigen::Vector3d& origin, double voxel_size) {
  CheckVoxelSize(voxel_size);
  return Overlap(CentreCodes(truth_centres, origin, voxel_size),
                 CentreCodes(occupied_centres, origin, voxel_size));
}

VoxelOverlap CompareWithSurface(const geometry::Mesh& truth,
                                const std::vector<Eigen::Vector3f>& occupied_centres,
                                const Eigen::Vector3d& origin, double voxel_size, uint64_t seed) {
  CheckVoxelSize(voxel_size);
  const std::vector<uint64_t> proxy = CentreCodes(occupied_centres, origin, voxel_size);
  const double density = 16.0 / (voxel_size * voxel_size);
  const SurfaceSamples samples = SampleSurface(truth, density, seed, 50'000'000);
  std::vector<uint64_t> surface;
  surface.reserve(samples.size());
  for (const Eigen::Vector3d& point : samples.points) {
    surface.push_back(Code(((point - origin) / voxel_size).array().floor().cast<int64_t>()));
  }
  return Overlap(SortedUnique(std::move(surface)), proxy);
}

}  // namespace avc::eval
