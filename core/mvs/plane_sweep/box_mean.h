#pragma once

// Windowed means for ZNCC. Our own separable running sum with double accumulators instead of
// cv::boxFilter: the result must not depend on how a library splits the image across threads.

#include <opencv2/core/mat.hpp>

namespace avc::mvs {

// dst = mean of src (CV_32F) over the (2 radius + 1)^2 window, the window clipped at the
// borders (mean over the part inside). dst is (re)allocated as CV_32F of src's size.
void BoxMean(const cv::Mat& src, int radius, cv::Mat& dst);

}  // namespace avc::mvs
