#pragma once

// URScript programs for the motions we command, as `def` programs (column-0 `def`/`end`, indented
// body; a new `def` aborts the running one). Joint targets are explicit (movej with q, never a
// pose, so the controller's IK branch choice never matters); poses are p[x,y,z,rx,ry,rz] in base
// with a rotation vector.

#include <array>
#include <string>

namespace avc::robot {

using Joints = std::array<double, 6>;
using PoseVector = std::array<double, 6>;  // x y z (m), rx ry rz (rad)

// Every generator throws std::invalid_argument for non-finite values or a, v <= 0.
std::string MoveJProgram(const Joints& q, double acceleration, double velocity);
std::string MoveLProgram(const PoseVector& pose, double acceleration, double velocity);
std::string StopJProgram(double deceleration);

}  // namespace avc::robot
