#pragma once

// The simulator reaches its views with the production view selection (core/cell/view_selection.h).

#include "core/cell/view_selection.h"
#include "sim/cell/cell_truth.h"

namespace avc::sim {

using cell::FirstReachableView;
using cell::JointsForCameraPose;
using cell::JointsLookingAt;
using cell::LookAtPose;
using cell::ReachableView;
using cell::RobotAzimuth;
using cell::StartJoints;
using cell::ViewpointOnSphere;

}  // namespace avc::sim
