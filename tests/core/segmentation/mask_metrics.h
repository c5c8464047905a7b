#pragma once

// Agreement of two binary masks, for the segmentation tests.

#include <opencv2/core.hpp>

namespace avc::segmentation::testing {

// Intersection over union of the non-zero pixels; 1 when both are empty.
inline double MaskIoU(const cv::Mat& a, const cv::Mat& b) {
  const cv::Mat in_a = a != 0, in_b = b != 0;
  const double both = cv::countNonZero(in_a & in_b);
  const double either = cv::countNonZero(in_a | in_b);
  return either > 0 ? both / either : 1.0;
}

// Fraction of the pixels selected by `where` that `mask` marks; 0 when `where` is empty.
inline double CoveredFraction(const cv::Mat& mask, const cv::Mat& where) {
  const double total = cv::countNonZero(where);
  return total > 0 ? cv::countNonZero((mask != 0) & (where != 0)) / total : 0.0;
}

}  // namespace avc::segmentation::testing
