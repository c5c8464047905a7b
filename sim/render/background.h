#pragma once

// The colour behind the scene at each pixel: plain, or a mottled cloth-like grey that is a
// function of the world-frame viewing direction (a distant backdrop), so it stays put relative to
// the scene as the camera moves and carries texture stereo can lock on to.

#include <Eigen/Core>
#include <vector>

#include "sim/render/lens_model.h"
#include "sim/render/render_options.h"

namespace avc::sim {

class BackgroundImage {
 public:
  BackgroundImage(const Background& background, const LensModel& lens,
                  const Eigen::Matrix3d& R_world_cam);
  // Linear RGB of pixels u0..u1-1 of row v into out[0..u1-u0).
  void Row(int v, int u0, int u1, Eigen::Vector3f* out) const;

 private:
  Eigen::Vector3f rgb_;
  bool plain_ = true;
  // kCloth: brightness factor on a coarse pixel grid, interpolated bilinearly (the mottling is
  // far coarser than the grid).
  int nodes_x_ = 0, nodes_y_ = 0;
  std::vector<float> factor_;
};

// The cloth pattern: brightness factor around 1 for a unit viewing direction.
float ClothFactor(const Background& background, const Eigen::Vector3d& direction_world);

}  // namespace avc::sim
