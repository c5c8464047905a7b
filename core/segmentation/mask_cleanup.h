#pragma once

// Tidies a thresholded plant mask without losing thin leaves: a small closing bridges
// one-pixel gaps and pin holes (closing only ever adds pixels, so 1-2 px wide structures
// survive), then connected specks much smaller than the plant are dropped.

#include <opencv2/core/mat.hpp>

namespace avc::segmentation {

struct CleanupOptions {
  int close_radius_px = 1;  // disc radius of the closing; 0 = no closing
  // Components (8-connected) smaller than this fraction of the largest one are dropped ...
  double min_component_fraction = 0.002;
  // ... and so are those smaller than this fraction of the image.
  double min_component_image_fraction = 5e-5;
};

// `mask` CV_8UC1, non-zero = object; returns a 255/0 mask of the same size.
cv::Mat CleanMask(const cv::Mat& mask, const CleanupOptions& options);

}  // namespace avc::segmentation
