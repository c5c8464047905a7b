#pragma once

// Which images to match an image against: those that look at the same part of the scene from a
// moderately different direction. Too small an angle gives poor depth, too large an angle
// little overlap and foreshortened patches.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::mvs {

struct NeighbourOptions {
  double min_angle = 0.05;        // radians (~3 deg): nearly identical views add little
  double max_angle = 1.05;        // radians (60 deg), PMVS's default angle limit
  double preferred_angle = 0.35;  // radians (20 deg): ranked best
  int max_neighbours = 8;
};

// Per view, the indices of its neighbours, best first (ties by index). Angles are between the
// rays from the camera centres to `scene_centre`; views that do not see the centre in front of
// them are nobody's neighbours.
std::vector<std::vector<uint32_t>> SelectNeighbours(const std::vector<camera::Camera>& cameras,
                                                    const Eigen::Vector3d& scene_centre,
                                                    const NeighbourOptions& options = {});

// The point nearest (least squares) to every camera's optical axis: where a ring of cameras
// looks. Falls back to the mean of the centres plus one metre along the mean axis when the axes
// are (nearly) parallel.
Eigen::Vector3d NearestPointToAxes(const std::vector<camera::Camera>& cameras);

}  // namespace avc::mvs
