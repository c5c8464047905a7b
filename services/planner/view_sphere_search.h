#pragma once

// The incremental view sphere (paper §2.2, Fig. 4) for one patch that is not seen well enough:
// candidate eyes on a sphere around the patch centre, first along the patch normal, then ring by
// ring at multiples of the ring step (each ring's points at equal angles around the normal). A
// candidate is acceptable when the arm reaches it (cell_view.h: any turntable angle, inside the
// limits, clear of the plant's box) and it sees the patch (patch_visibility.h). The paper takes
// the first acceptable one; given a `rank`, the acceptable candidates of the first ring that has
// any are ranked and the best taken (ties: the first), so one view can serve several patches.

#include <functional>
#include <optional>

#include "core/ppr/plant_proxy.h"
#include "services/planner/cell_view.h"
#include "services/planner/patch_visibility.h"
#include "services/planner/proxy_patches.h"

namespace avc::planner {

struct SphereSearch {
  double radius = 0.5;             // metres from the patch centre
  double ring_step = 0.1745;       // radians between rings
  int rings = 9;                   // rings after the normal (9 x 10 degrees: the tangent plane)
  int max_ranked = 8;              // acceptable candidates of a ring ranked at most
  double min_seen_fraction = 0.5;  // of the patch's faces the view must see
};

struct SphereSearchResult {
  std::optional<CellView> view;
  int candidates = 0;  // eyes tried
  int ring = -1;       // ring of the chosen eye (0: on the normal)
};

// Higher is better; e.g. how many failing patches the view would see.
using ViewRank = std::function<double(const CellView& view)>;

SphereSearchResult SearchViewSphere(const cell::CellModel& cell, const ppr::PlantProxy& proxy,
                                    const SurfacePatch& patch, const SphereSearch& search,
                                    const kinematics::JointVector& current,
                                    const ReachOptions& reach, const VisibilityOptions& visibility,
                                    const ViewRank& rank = {});

}  // namespace avc::planner
