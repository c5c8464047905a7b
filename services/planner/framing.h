#pragma once

// Framing (Algorithm 1 line 4): from live-view frames, the distance and aim at one height that
// make the colour-filtered plant fill a wanted fraction of the field of view. Each frame's mask
// gives the plant's extent (its bounding box over the image's size) and its centre; the distance
// scales with extent / wanted (a pinhole's image size goes as 1 / distance) and the aim moves
// up or down to the centre's height on the turntable axis.

#include <Eigen/Core>
#include <functional>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <utility>

#include "services/planner/cell_view.h"

namespace avc::planner {

struct Framing {
  double distance = 0;                            // metres from the aim
  Eigen::Vector3d aim = Eigen::Vector3d::Zero();  // world, on the turntable axis
  double fill = 0;  // the plant's extent over the image's in the last frame
  int frames = 0;
  std::string note;  // set when the plant could not be framed as wanted (too big, too small)
};

struct FramingRequest {
  double elevation = 0.5;  // radians
  double start_distance = 0.6;
  double start_aim_height = 0.12;
  double fill = 0.75;
  double tolerance = 0.1;
  int iterations = 4;
};

// `frame` realises and takes a live-view frame at (distance, aim) and returns its mask, or
// nullopt when no view there is reachable or the frame failed. Throws std::runtime_error when
// no frame shows any plant (the colour filter found nothing), naming the height.
using FrameFunction = std::function<std::optional<std::pair<CellView, cv::Mat>>(
    double distance, const Eigen::Vector3d& aim)>;
Framing FramePlant(const FramingRequest& request, const FrameFunction& frame);

}  // namespace avc::planner
