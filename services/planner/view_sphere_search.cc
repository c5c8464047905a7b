#include "services/planner/view_sphere_search.h"

#include <algorithm>
#include <cmath>

namespace avc::planner {
namespace {

// Two unit vectors completing `normal` to a right-handed basis, chosen the same way every time.
std::pair<Eigen::Vector3d, Eigen::Vector3d> TangentBasis(const Eigen::Vector3d& normal) {
  const Eigen::Vector3d helper =
      std::abs(normal.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d u = normal.cross(helper).normalized();
  return {u, normal.cross(u)};
}

}  // namespace

SphereSearchResult SearchViewSphere(const cell::CellModel& cell, const ppr::PlantProxy& proxy,
                                    const SurfacePatch& patch, const SphereSearch& search,
                                    const kinematics::JointVector& current,
                                    const ReachOptions& reach, const VisibilityOptions& visibility,
                                    const ViewRank& rank) {
  SphereSearchResult result;
  const auto [u, v] = TangentBasis(patch.normal);
  const Eigen::AlignedBox3d keep_out = proxy.OccupiedBounds();
  double best = 0;  // rank of result.view
  int ranked = 0;
  for (int ring = 0; ring <= search.rings; ++ring) {
    const double theta = ring * search.ring_step;
    const int around = ring == 0 ? 1
                                 : std::max(1, static_cast<int>(std::lround(
                                                   2 * M_PI * std::sin(theta) / search.ring_step)));
    for (int j = 0; j < around; ++j) {
      const double phi = 2 * M_PI * j / around;
      const Eigen::Vector3d direction = std::cos(theta) * patch.normal +
                                        std::sin(theta) * (std::cos(phi) * u + std::sin(phi) * v);
      const Eigen::Vector3d eye = patch.centre + search.radius * direction;
      ++result.candidates;
      const auto view = RealiseView(cell, eye, patch.centre, keep_out, current, reach);
      if (!view) continue;
      if (SeenFraction(proxy, patch, view->camera, visibility) < visibility.min_seen_fraction) {
        continue;
      }
      if (!rank) {
        result.view = view;
        result.ring = ring;
        return result;
      }
      const double value = rank(*view);
      if (!result.view || value > best) {
        result.view = view;
        result.ring = ring;
        best = value;
      }
      if (++ranked >= search.max_ranked) break;
    }
    if (result.view) return result;
  }
  return result;
}

}  // namespace avc::planner
