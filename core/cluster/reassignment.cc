#include "core/cluster/reassignment.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/cluster/pca.h"
#include "core/cluster/point_set.h"

namespace avc::cluster {

size_t ReassignDistalPoints(const PointGrid& grid, const std::vector<Eigen::Vector3f>& points,
                            const std::vector<Eigen::Vector3f>& normals, float link_radius,
                            int max_rounds, std::vector<int32_t>* cluster_of) {
  std::vector<int32_t>& owner = *cluster_of;
  int32_t clusters = 0;
  for (int32_t c : owner) clusters = std::max(clusters, c + 1);
  size_t total_moves = 0;
  for (int round = 0; round < max_rounds; ++round) {
    std::vector<std::vector<uint32_t>> members(static_cast<size_t>(clusters));
    for (size_t i = 0; i < owner.size(); ++i) {
      if (owner[i] != kUnassigned) members[static_cast<size_t>(owner[i])].push_back(i);
    }
    std::vector<PrincipalAxes> fit(members.size());
    for (size_t c = 0; c < members.size(); ++c) {
      if (!members[c].empty()) fit[c] = FitPrincipalAxes(points, members[c]);
    }
    std::vector<int32_t> next = owner;
    size_t moves = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const int32_t a = owner[i];
      if (a == kUnassigned) continue;
      const Eigen::Vector3d p = points[i].cast<double>();
      const Eigen::Vector3d n = normals[i].cast<double>();
      const PrincipalAxes& own = fit[static_cast<size_t>(a)];
      const double own_centroid = (p - own.centroid).norm();
      const double own_align = std::abs(n.dot(own.PlaneNormal()));
      const double own_plane = std::abs((p - own.centroid).dot(own.PlaneNormal()));
      int32_t best = a;
      double best_centroid = own_centroid;
      grid.ForEachWithin(points[i], link_radius, [&](uint32_t j) {
        const int32_t b = owner[j];
        if (b == kUnassigned || b == a || b == best) return;
        const PrincipalAxes& other = fit[static_cast<size_t>(b)];
        const double centroid = (p - other.centroid).norm();
        if (centroid >= best_centroid) return;
        if (std::abs(n.dot(other.PlaneNormal())) <= own_align) return;
        if (std::abs((p - other.centroid).dot(other.PlaneNormal())) >= own_plane) return;
        best = b;
        best_centroid = centroid;
      });
      if (best != a) {
        next[i] = best;
        ++moves;
      }
    }
    owner = std::move(next);
    total_moves += moves;
    if (moves == 0) break;
  }
  return total_moves;
}

size_t MergeSpuriousGroups(const PointGrid& grid, const std::vector<Eigen::Vector3f>& points,
                           const std::vector<std::vector<uint32_t>>& groups, float link_radius,
                           std::vector<int32_t>* cluster_of) {
  std::vector<int32_t>& owner = *cluster_of;
  size_t unassigned = 0;
  for (const std::vector<uint32_t>& group : groups) {
    std::map<int32_t, size_t> votes;  // ordered: ties go to the lower cluster id
    for (uint32_t i : group) {
      grid.ForEachWithin(points[i], link_radius, [&](uint32_t j) {
        if (owner[j] != kUnassigned) ++votes[owner[j]];
      });
    }
    int32_t target = kUnassigned;
    size_t most = 0;
    for (const auto& [cluster, count] : votes) {
      if (count > most) {
        most = count;
        target = cluster;
      }
    }
    for (uint32_t i : group) owner[i] = target;
    if (target == kUnassigned) unassigned += group.size();
  }
  return unassigned;
}

}  // namespace avc::cluster
