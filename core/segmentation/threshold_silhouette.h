#pragma once

// The Middlebury multi-view recipe for silhouettes of a bright object on black (dataset
// README): threshold the [0, 1] intensity, dilate, then erode. Used as the reference
// silhouettes by benchmarks and tests ("fraction of points inside every silhouette").

#include <opencv2/core/mat.hpp>

namespace avc::segmentation {

// Intensity is the grey value / 255 (cv::COLOR_BGR2GRAY for colour input); object pixels have
// intensity > threshold_0_to_1. Dilation then erosion use discs (ellipses) of radius dilate_px
// and erode_px (0 = skip). `image` is CV_8UC3 (BGR) or CV_8UC1. Returns CV_8UC1, 255 / 0.
// Middlebury's values: ThresholdSilhouette(image, 0.19, 10, 7).
// Throws std::invalid_argument for an empty image, another pixel type, a threshold outside
// [0, 1] or a negative radius.
cv::Mat ThresholdSilhouette(const cv::Mat& image, double threshold_0_to_1, int dilate_px,
                            int erode_px);

}  // namespace avc::segmentation
