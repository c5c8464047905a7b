#include "core/dataset/view_transforms.h"

#include <fmt/format.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::dataset {

void Undistort(View& view) {
  auto& k = view.camera.intrinsics;
  if (!k.HasDistortion()) return;
  const cv::Matx33d matrix(k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1);
  const cv::Mat coefficients(1, 5, CV_64F, k.distortion.data());
  cv::Mat map_x, map_y;
  cv::initUndistortRectifyMap(matrix, coefficients, cv::Mat(), matrix, view.image.size(), CV_32FC1,
                              map_x, map_y);
  cv::Mat image;
  cv::remap(view.image, image, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
  view.image = image;
  if (!view.mask.empty()) {
    cv::Mat mask;
    cv::remap(view.mask, mask, map_x, map_y, cv::INTER_NEAREST, cv::BORDER_CONSTANT);
    view.mask = mask;
  }
  k.distortion = {};
}

View AtPyramidLevel(const View& view, int level) {
  if (level < 0) throw std::invalid_argument("pyramid level must be 0 or more");
  View out = view;
  for (int i = 0; i < level; ++i) {
    if (out.image.cols < 32 || out.image.rows < 32) {
      throw std::invalid_argument(fmt::format("{}: {}x{} is too small for pyramid level {}",
                                              view.name, view.image.cols, view.image.rows, level));
    }
    cv::Mat image;
    cv::pyrDown(out.image, image);
    out.image = image;
    if (!out.mask.empty()) {
      cv::Mat mask;
      cv::resize(out.mask, mask, out.image.size(), 0, 0, cv::INTER_NEAREST);
      out.mask = mask;
    }
    // pyrDown's pixel i is centred on the old pixel 2i, so coordinates simply halve.
    auto& k = out.camera.intrinsics;
    k.width = out.image.cols;
    k.height = out.image.rows;
    k.fx /= 2;
    k.fy /= 2;
    k.cx /= 2;
    k.cy /= 2;
  }
  return out;
}

}  // namespace avc::dataset
