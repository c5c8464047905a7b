#include "bench/nbv/simulated_capture.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/segmentation/plant_mask.h"

namespace avc::bench {

SimulatedCapture::SimulatedCapture(const sim::Scene& scene, double scale)
    : scene_(scene), scale_(scale) {}

std::optional<cv::Mat> SimulatedCapture::operator()(const planner::CellView& view) {
  camera::Camera small = view.camera;
  camera::Intrinsics& k = small.intrinsics;
  const int width = k.width;
  const int height = k.height;
  k.width = static_cast<int>(std::lround(width * scale_));
  k.height = static_cast<int>(std::lround(height * scale_));
  // Pixel centres at integers: the scaled principal point keeps the same rays.
  k.fx *= scale_;
  k.fy *= scale_;
  k.cx = (k.cx + 0.5) * scale_ - 0.5;
  k.cy = (k.cy + 0.5) * scale_ - 0.5;
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
