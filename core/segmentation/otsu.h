#pragma once

// Otsu's automatic threshold on a real-valued feature image, with the separability measure
// eta = between-class variance / total variance that says how cleanly the two classes split
// (1 = two spikes, about 0.64 for a single Gaussian, 0 for a constant image).

#include <opencv2/core/mat.hpp>

namespace avc::segmentation {

struct OtsuSplit {
  double threshold = 0;     // foreground is value > threshold
  double separability = 0;  // eta in [0, 1]
};

// Otsu on a histogram of `bins` equal bins between the feature's minimum and maximum.
// `values` is CV_32FC1 with finite entries. A constant image gives threshold = that value and
// separability 0 (nothing is above it). Throws std::invalid_argument on an empty or non-float
// image or bins < 2.
OtsuSplit OtsuThreshold(const cv::Mat& values, int bins);

// eta of splitting `values` (CV_32FC1) at `threshold`, computed exactly from the pixels.
double SplitSeparability(const cv::Mat& values, double threshold);

}  // namespace avc::segmentation
