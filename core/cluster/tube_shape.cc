#include "core/cluster/tube_shape.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace avc::cluster {
namespace {

// A tube's normals face every way round its axis. A blade arched or curled along its length
// also has normals along its offsets from the chord, but in fewer directions.
constexpr int kSectors = 8;
constexpr int kMinFilledSectors = 6;

int SectorOf(const Eigen::Vector3d& radial, const PrincipalAxes& axes) {
  const double angle = std::atan2(radial.dot(axes.axes.col(1)), radial.dot(axes.axes.col(0)));
  const int sector =
      static_cast<int>(std::floor((angle + std::numbers::pi) / (2 * std::numbers::pi) * kSectors));
  return std::clamp(sector, 0, kSectors - 1);
}

}  // namespace

bool IsTube(const std::vector<Eigen::Vector3f>& points, const std::vector<Eigen::Vector3f>& normals,
            const std::vector<uint32_t>& cluster, const PrincipalAxes& axes, const TubeRule& rule) {
  const Eigen::Vector3d axis = axes.LongestAxis();
  std::vector<double> alignments;
  alignments.reserve(cluster.size());
  std::array<bool, kSectors> filled{};
  double distance_sum = 0;
  double distance_square_sum = 0;
  for (uint32_t i : cluster) {
    const Eigen::Vector3d offset = points[i].cast<double>() - axes.centroid;
    const Eigen::Vector3d radial = offset - offset.dot(axis) * axis;
    const double distance = radial.norm();
    if (distance <= 1e-9) continue;
    distance_sum += distance;
    distance_square_sum += distance * distance;
    const double alignment = std::abs(radial.dot(normals[i].cast<double>())) / distance;
    alignments.push_back(alignment);
    if (alignment >= rule.min_alignment) filled[static_cast<size_t>(SectorOf(radial, axes))] = true;
  }
  if (alignments.empty()) return false;
  if (std::count(filled.begin(), filled.end(), true) < kMinFilledSectors) return false;
  const double count = static_cast<double>(alignments.size());
  const double mean_distance = distance_sum / count;
  const double spread =
      std::sqrt(std::max(0.0, distance_square_sum / count - mean_distance * mean_distance));
  if (spread > rule.max_radius_spread * mean_distance) return false;
  const auto median = alignments.begin() + static_cast<std::ptrdiff_t>(alignments.size() / 2);
  std::nth_element(alignments.begin(), median, alignments.end());
  return *median >= rule.min_alignment;
}

}  // namespace avc::cluster
