#pragma once

// Which way is up in an imported dataset. AVC's world has z up (plant height, the soil and the
// support are measured along it); some scanners' worlds do not (ROMI's has z down). Cameras of a
// plant scan are held upright, so the mean of their image-up directions (-y of each camera, in
// the world) points up. When the cameras agree on it and it is nearest another world axis than
// +z, the import turns the world by the quarter or half turn that brings that axis to +z: an
// exact rotation (entries 0 and +-1), so lengths and the cameras' relations are untouched.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::dataset {

// The cameras must agree this much: |mean of their unit up directions| (1 = all parallel).
inline constexpr double kMinUpAgreement = 0.5;

struct UprightTurn {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // world' = rotation * world
  std::string from_axis;  // the file's axis that becomes +z: "-z", "+x", ...
};

// nullopt when +z is already up, or the cameras do not agree on an up direction.
std::optional<UprightTurn> FindUprightTurn(const std::vector<camera::Camera>& cameras);

// True when the cameras agree that +z is up (the mean of their image-up directions has a +z
// component of at least kMinUpAgreement): "below the plant" means something.
bool CamerasAgreeZIsUp(const std::vector<camera::Camera>& cameras);

}  // namespace avc::dataset
