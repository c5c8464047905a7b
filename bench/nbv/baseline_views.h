#pragma once

// The view sets the planner is compared with (issue 7), realised in the same cell and around the
// same framed aim as the planner's views: one static camera with the turntable, two static
// cameras (one level, one higher looking down), and random reachable views. Each returns at
// most `count` views (fewer when some are unreachable, which the caller reports).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "services/planner/cell_view.h"
#include "sim/cell/cell_truth.h"

namespace avc::planner {

struct BaselineFrame {
  Eigen::Vector3d aim = Eigen::Vector3d::Zero();  // world, on the turntable axis
  double distance = 0.5;                          // metres
};

// One camera at `elevation` (radians), the turntable stepping through `count` angles.
std::vector<CellView> StaticCameraViews(const sim::CellTruth& cell, const BaselineFrame& frame,
                                        double elevation, int count);

// Two cameras, count / 2 turntable angles each: one at `low` and one at `high` elevation.
std::vector<CellView> TwoStaticCameraViews(const sim::CellTruth& cell, const BaselineFrame& frame,
                                           double low, double high, int count);

// Views on elevation rings x `azimuths` equal steps, each realised from the start joints (the
// branch the arm returns to between views); the unreachable ones are left out. With many
// views, their coverage is the ceiling any selection from the sphere can reach.
std::vector<CellView> SphereViews(const sim::CellTruth& cell, const BaselineFrame& frame,
                                  const std::vector<double>& elevations, int azimuths);

// Views at uniformly random directions above 5 degrees and below 75 degrees elevation, at
// 0.9-1.1 times the distance; unreachable draws are skipped (at most 50 draws per view).
std::vector<CellView> RandomViews(const sim::CellTruth& cell, const BaselineFrame& frame, int count,
                                  uint64_t seed);

}  // namespace avc::planner
