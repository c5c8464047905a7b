#pragma once

// The planner's Capture in the simulated cell without the bus: the plant rendered from a view's
// camera at a fraction of the camera's resolution, masked by the builder's automatic segmentation
// and scaled back to the camera's size, as the proxy expects. Counts the pictures it takes.

#include <opencv2/core/mat.hpp>
#include <optional>

#include "services/planner/cell_view.h"
#include "sim/render/renderer.h"
#include "sim/scene/scene.h"

namespace avc::bench {

// The camera at `scale` times its resolution, with the same rays (pixel centres at integers).
camera::Camera ScaledCamera(const camera::Camera& camera, double scale);

class SimulatedCapture {
 public:
  // `scale`: render size over the camera's (0.5: 640x480 for the cell's 1280x960 camera).
  SimulatedCapture(const sim::Scene& scene, double scale);

  std::optional<cv::Mat> operator()(const planner::CellView& view);
  int captures() const { return captures_; }

 private:
  const sim::Scene& scene_;
  double scale_;
  sim::Renderer renderer_;
  sim::RenderResult frame_;
  int captures_ = 0;
};

}  // namespace avc::bench
