#include "core/cluster/reassignment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/cluster/pca.h"
#include "core/cluster/point_set.h"

namespace avc::cluster {

namespace {

// The points of one cluster around a query point.
struct LocalPart {
  int32_t cluster = kUnassigned;
  std::vector<uint32_t> members;
};

// Distance of p to the part's regression plane and |n . plane normal|; a part of fewer than 3
// points has no plane (infinitely far, not aligned).
struct LocalFit {
  double plane_distance = std::numeric_limits<double>::infinity();
  double alignment = 0.0;
};

LocalFit FitLocally(const std::vector<Eigen::Vector3f>& points, const std::vector<uint32_t>& part,
                    const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
  LocalFit fit;
  if (part.size() < 3) return fit;
  const PrincipalAxes axes = FitPrincipalAxes(points, part);
  fit.plane_distance = std::abs((p - axes.centroid).dot(axes.PlaneNormal()));
  fit.alignment = std::abs(n.dot(axes.PlaneNormal()));
  return fit;
}

}  // namespace

size_t ReassignDistalPoints(const PointGrid& grid, const std::vector<Eigen::Vector3f>& points,
                            const std::vector<Eigen::Vector3f>& normals, float link_radius,
                            int max_rounds, std::vector<int32_t>* cluster_of) {
  std::vector<int32_t>& owner = *cluster_of;
  size_t total_moves = 0;
  std::vector<LocalPart> parts;
  std::vector<uint32_t> around;
  // A decision depends only on the owners within link_radius, so after the first round only the
  // points near a move need another look.
  std::vector<uint8_t> unsettled(points.size(), 1);
  for (int round = 0; round < max_rounds; ++round) {
    std::vector<int32_t> next = owner;
    size_t moves = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const int32_t a = owner[i];
      if (a == kUnassigned || !unsettled[i]) continue;
      around.clear();
      bool foreign = false;
      grid.ForEachWithin(points[i], link_radius, [&](uint32_t j) {
        if (owner[j] == kUnassigned) return;
        around.push_back(j);
        foreign = foreign || owner[j] != a;
      });
      if (!foreign) continue;  // inside its cluster: nothing to compare
      // The clusters around p, own first, others in order of first appearance (deterministic).
      parts.assign(1, LocalPart{a, {}});
      for (uint32_t j : around) {
        const int32_t b = owner[j];
        auto part = std::find_if(parts.begin(), parts.end(),
                                 [&](const LocalPart& q) { return q.cluster == b; });
        if (part == parts.end()) part = parts.insert(parts.end(), LocalPart{b, {}});
        part->members.push_back(j);
      }
      const Eigen::Vector3d p = points[i].cast<double>();
      const Eigen::Vector3d n = normals[i].cast<double>();
      const LocalFit own = FitLocally(points, parts[0].members, p, n);
      // The other cluster whose local plane fits p best, if it fits better than p's own.
      int32_t best = a;
      double best_distance = own.plane_distance;
      for (size_t k = 1; k < parts.size(); ++k) {
        const LocalFit other = FitLocally(points, parts[k].members, p, n);
        if (other.alignment <= own.alignment || other.plane_distance >= best_distance) continue;
        best = parts[k].cluster;
        best_distance = other.plane_distance;
      }
      if (best != a) {
        next[i] = best;
        ++moves;
      }
    }
    std::fill(unsettled.begin(), unsettled.end(), 0);
    for (size_t i = 0; i < points.size(); ++i) {
      if (next[i] == owner[i]) continue;
      grid.ForEachWithin(points[i], link_radius, [&](uint32_t j) { unsettled[j] = 1; });
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

size_t RejoinStrandedParts(const NeighbourLists& neighbours, size_t min_points,
                           std::vector<int32_t>* scratch, std::vector<int32_t>* cluster_of) {
  std::vector<int32_t>& owner = *cluster_of;
  int32_t clusters = 0;
  for (int32_t id : owner) clusters = std::max(clusters, id + 1);
  std::vector<std::vector<uint32_t>> members(static_cast<size_t>(clusters));
  for (size_t i = 0; i < owner.size(); ++i) {
    if (owner[i] != kUnassigned) members[owner[i]].push_back(static_cast<uint32_t>(i));
  }
  std::vector<std::pair<std::vector<uint32_t>, int32_t>> moves;
  std::vector<size_t> links(static_cast<size_t>(clusters));
  for (int32_t c = 0; c < clusters; ++c) {
    const auto parts = ConnectedComponents(neighbours, members[c], scratch);
    if (parts.size() < 2) continue;
    const auto largest =
        std::max_element(parts.begin(), parts.end(),
                         [](const auto& a, const auto& b) { return a.size() < b.size(); });
    for (auto part = parts.begin(); part != parts.end(); ++part) {
      if (part == largest || part->size() >= min_points) continue;
      std::fill(links.begin(), links.end(), 0);
      for (uint32_t i : *part) {
        for (const uint32_t* j = neighbours.begin(i); j != neighbours.end(i); ++j) {
          if (owner[*j] != kUnassigned && owner[*j] != c) ++links[owner[*j]];
        }
      }
      const auto most = std::max_element(links.begin(), links.end());
      if (*most > 0) moves.emplace_back(*part, static_cast<int32_t>(most - links.begin()));
    }
  }
  size_t moved = 0;
  for (const auto& [part, target] : moves) {
    for (uint32_t i : part) owner[i] = target;
    moved += part.size();
  }
  return moved;
}

}  // namespace avc::cluster
