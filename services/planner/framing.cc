#include "services/planner/framing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::planner {

Framing FramePlant(const FramingRequest& request, const FrameFunction& frame) {
  Framing framing;
  framing.distance = request.start_distance;
  framing.aim = Eigen::Vector3d(0, 0, request.start_aim_height);
  bool saw_plant = false;
  double framed_distance = framing.distance;  // of the last frame that showed the plant
  for (int i = 0; i < request.iterations; ++i) {
    const auto taken = frame(framing.distance, framing.aim);
    ++framing.frames;
    if (!taken) {
      // Unreachable there: come closer, where the arm reaches more.
      framing.distance *= 0.85;
      continue;
    }
    const auto& [view, mask] = *taken;
    const cv::Rect box = cv::boundingRect(mask);
    if (box.area() == 0) continue;
    saw_plant = true;
    framed_distance = framing.distance;
    const camera::Intrinsics& k = view.camera.intrinsics;
    framing.fill = std::max(static_cast<double>(box.width) / k.width,
                            static_cast<double>(box.height) / k.height);
    // Aim at the plant's centre: the centre pixel's ray at the aim's depth, projected onto the
    // turntable axis (the plant stands on it).
    const Eigen::Vector2d centre(box.x + 0.5 * box.width, box.y + 0.5 * box.height);
    const Eigen::Vector3d ray_world = view.camera.T_cam_world.inverse().linear() * k.Ray(centre);
    const Eigen::Vector3d hit = view.centre_world + ray_world * framing.distance;
    framing.aim.z() = std::max(0.0, hit.z());
    const bool touches_border =
        box.x <= 0 || box.y <= 0 || box.x + box.width >= k.width || box.y + box.height >= k.height;
    const double wanted = request.fill;
    if (!touches_border && std::abs(framing.fill - wanted) <= request.tolerance) return framing;
    // Cut off by the border: the true extent is larger than measured, so step back further.
    const double scale =
        touches_border ? std::max(1.3, framing.fill / wanted) : framing.fill / wanted;
    framing.distance *= scale;
  }
  if (!saw_plant) {
    throw std::runtime_error(fmt::format(
        "framing at elevation {:.0f} deg: no plant found by the colour filter in {} live-view "
        "frames (is a plant on the turntable, in view and lit?)",
        request.elevation * 180 / M_PI, framing.frames));
  }
  framing.distance = framed_distance;
  framing.note = fmt::format(
      "framing at elevation {:.0f} deg: the plant fills {:.0f} % of the view after {} frames "
      "(wanted {:.0f} %); the arm's reach or the plant's size limits it",
      request.elevation * 180 / M_PI, 100 * framing.fill, framing.frames, 100 * request.fill);
  return framing;
}

}  // namespace avc::planner
