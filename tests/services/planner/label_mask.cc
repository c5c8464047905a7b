#include "tests/services/planner/label_mask.h"

#include <opencv2/imgproc.hpp>

#include "core/geometry/mesh.h"
#include "sim/render/renderer.h"

namespace avc::testing {

cv::Mat LabelMask(const sim::Scene& scene, const camera::Camera& camera) {
  camera::Camera small = camera;
  camera::Intrinsics& k = small.intrinsics;
  const cv::Size full(k.width, k.height);
  k.width /= 4;
  k.height /= 4;
  k.fx /= 4;
  k.fy /= 4;
  k.cx = (k.cx + 0.5) / 4 - 0.5;
  k.cy = (k.cy + 0.5) / 4 - 0.5;
  sim::RenderOptions options;
  options.samples_per_pixel_axis = 1;
  const cv::Mat mask = sim::Render(scene, small, options).labels >= geometry::labels::kStem;
  cv::Mat resized;
  cv::resize(mask, resized, full, 0, 0, cv::INTER_NEAREST);
  return resized;
}

}  // namespace avc::testing
