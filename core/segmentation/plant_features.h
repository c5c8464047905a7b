#pragma once

// Per-pixel features that separate a plant from its surroundings; each is thresholded
// automatically (Otsu) by SegmentPlant. Larger values mean "more likely object".

#include <opencv2/core/mat.hpp>

namespace avc::segmentation {

// Excess green on chromaticity, ExG = 2g - r - b with r, g, b = R, G, B / (R + G + B), in
// [-1, 2]; grey and brown give about 0 or below, foliage clearly above. Chromaticity of very
// dark pixels is mostly noise, so the sum is floored at `dark_fraction` times the image's bright
// level (99th percentile of R + G + B): dark pixels fade towards 0, i.e. towards background.
// `bgr` is CV_8UC3; returns CV_32FC1.
cv::Mat ExcessGreen(const cv::Mat& bgr, double dark_fraction);

// The background colour model, estimated from a strip along the image border.
struct BackgroundModel {
  cv::Vec3f median_lab;  // CIE L*a*b* (L 0..100)
  cv::Vec3f scale_lab;   // per-channel robust spread: max(1.4826 MAD, min_scale)
};

// Median and MAD of the border strip (width: max(1, round(border_fraction * min(w, h))) px)
// in L*a*b*. The median tolerates the object touching up to about half of the border.
BackgroundModel EstimateBorderBackground(const cv::Mat& bgr, double border_fraction,
                                         double min_scale);

// Distance of every pixel from the background model: Euclidean in L*a*b* with each channel
// divided by its robust spread, so a mottled backdrop (large L spread) does not look like
// object while a colour change does. Returns CV_32FC1.
cv::Mat BackgroundDistance(const cv::Mat& bgr, const BackgroundModel& model);

}  // namespace avc::segmentation
