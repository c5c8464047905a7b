#include "core/cluster/point_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace avc::cluster {
namespace {
// Upper bound on cells so a few far outliers cannot blow up memory.
constexpr double kMaxCells = 4.0e6;
}  // namespace

PointGrid::PointGrid(const std::vector<Eigen::Vector3f>& points, float cell_size)
    : points_(points), cell_size_(cell_size) {
  if (!(cell_size > 0.0f) || !std::isfinite(cell_size)) {
    throw std::invalid_argument("PointGrid: cell size must be positive and finite");
  }
  Eigen::Vector3f lo = Eigen::Vector3f::Zero();
  Eigen::Vector3f hi = Eigen::Vector3f::Zero();
  if (!points.empty()) {
    lo = hi = points[0];
    for (const Eigen::Vector3f& p : points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  const Eigen::Vector3d extent = (hi - lo).cast<double>();
  while ((std::floor(extent.x() / cell_size_) + 1) * (std::floor(extent.y() / cell_size_) + 1) *
             (std::floor(extent.z() / cell_size_) + 1) >
         kMaxCells) {
    cell_size_ *= 2.0f;
  }
  origin_ = lo;
  for (int a = 0; a < 3; ++a) dims_[a] = static_cast<int>(std::floor(extent[a] / cell_size_)) + 1;
  const size_t cells = static_cast<size_t>(dims_.x()) * dims_.y() * dims_.z();
  std::vector<uint32_t> cell_of(points.size());
  std::vector<uint32_t> counts(cells + 1, 0);
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3i c = CellOf(points[i]);
    cell_of[i] =
        static_cast<uint32_t>((static_cast<size_t>(c.z()) * dims_.y() + c.y()) * dims_.x() + c.x());
    ++counts[cell_of[i] + 1];
  }
  for (size_t c = 0; c < cells; ++c) counts[c + 1] += counts[c];
  cell_start_ = counts;
  order_.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    order_[counts[cell_of[i]]++] = static_cast<uint32_t>(i);
}

Eigen::Vector3i PointGrid::CellOf(const Eigen::Vector3f& p) const {
  Eigen::Vector3i c;
  for (int a = 0; a < 3; ++a) {
    const int v = static_cast<int>(std::floor((p[a] - origin_[a]) / cell_size_));
    c[a] = std::clamp(v, 0, dims_[a] - 1);
  }
  return c;
}

}  // namespace avc::cluster
