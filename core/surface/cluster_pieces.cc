#include "core/surface/cluster_pieces.h"

#include <numeric>

#include "core/cluster/connected_components.h"
#include "core/cluster/point_grid.h"

namespace avc::surface {

std::vector<std::vector<uint32_t>> SplitIntoPieces(const ClusteredPoints& input,
                                                   const std::vector<uint32_t>& members,
                                                   double link_radius, double allowance) {
  if (members.size() < 2) return {members};
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> normals;
  points.reserve(members.size());
  for (uint32_t i : members) {
    points.push_back(input.cloud.positions[i]);
    if (!input.cloud.normals.empty()) normals.push_back(input.cloud.normals[i].normalized());
  }
  cluster::LinkRule rule;
  rule.radius = static_cast<float>(link_radius);
  rule.normals = normals.empty() ? nullptr : &normals;
  rule.allowance = static_cast<float>(allowance);
  rule.mean_slope = cluster::kSameSurfaceMeanSlope;  // as the clusterer: stacked leaves apart
  const cluster::PointGrid grid(points, rule.radius);
  std::vector<uint32_t> local(members.size());
  std::iota(local.begin(), local.end(), 0u);
  std::vector<int32_t> scratch(members.size(), -1);
  std::vector<std::vector<uint32_t>> pieces =
      cluster::ConnectedComponents(grid, points, local, rule, &scratch);
  for (std::vector<uint32_t>& piece : pieces) {
    for (uint32_t& k : piece) k = members[k];
  }
  return pieces;
}

}  // namespace avc::surface
