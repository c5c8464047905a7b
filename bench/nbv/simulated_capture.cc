#include "bench/nbv/simulated_capture.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/segmentation/plant_mask.h"

namespace avc::bench {

camera::Camera ScaledCamera(const camera::Camera& camera, double scale) {
  camera::Camera scaled = camera;
  camera::Intrinsics& k = scaled.intrinsics;
  k.width = static_cast<int>(std::lround(k.width * scale));
  k.height = static_cast<int>(std::lround(k.height * scale));
  k.fx *= scale;
  k.fy *= scale;
  k.cx = (k.cx + 0.5) * scale - 0.5;
  k.cy = (k.cy + 0.5) * scale - 0.5;
  return scaled;
}

SimulatedCapture::SimulatedCapture(const sim::Scene& scene, double scale)
    : scene_(scene), scale_(scale) {}

std::optional<cv::Mat> SimulatedCapture::operator()(const planner::CellView& view) {
  const camera::Camera small = ScaledCamera(view.camera, scale_);
  const int width = view.camera.intrinsics.width;
  const int height = view.camera.intrinsics.height;
  sim::RenderOptions options;
  options.samples_per_pixel_axis = 1;
  renderer_.Render(scene_, small, options, &frame_);
  ++captures_;
  const cv::Mat mask = segmentation::SegmentPlant(frame_.color).mask;
  cv::Mat full;
  cv::resize(mask, full, cv::Size(width, height), 0, 0, cv::INTER_NEAREST);
  return full;
}

}  // namespace avc::bench
