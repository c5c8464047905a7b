#include "core/segmentation/threshold_silhouette.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace avc::segmentation {
namespace {

cv::Mat Disc(int radius) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
}

}  // namespace

cv::Mat ThresholdSilhouette(const cv::Mat& image, double threshold_0_to_1, int dilate_px,
                            int erode_px) {
  if (image.empty()) throw std::invalid_argument("ThresholdSilhouette: empty image");
  if (image.type() != CV_8UC3 && image.type() != CV_8UC1) {
    throw std::invalid_argument("ThresholdSilhouette: image must be CV_8UC3 or CV_8UC1, got type " +
                                std::to_string(image.type()));
  }
  if (!(threshold_0_to_1 >= 0.0 && threshold_0_to_1 <= 1.0)) {
    throw std::invalid_argument("ThresholdSilhouette: threshold must be in [0, 1], got " +
                                std::to_string(threshold_0_to_1));
  }
  if (dilate_px < 0 || erode_px < 0) {
    throw std::invalid_argument("ThresholdSilhouette: dilate_px and erode_px must be >= 0");
  }
  cv::Mat grey;
  if (image.channels() == 3) {
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  } else {
    grey = image;
  }
  // Compare in [0, 1] exactly as the recipe states, not on a rounded 8-bit level.
  cv::Mat intensity;
  grey.convertTo(intensity, CV_32F, 1.0 / 255.0);
  cv::Mat mask = intensity > threshold_0_to_1;
  if (dilate_px > 0) cv::dilate(mask, mask, Disc(dilate_px));
  if (erode_px > 0) cv::erode(mask, mask, Disc(erode_px));
  return mask;
}

}  // namespace avc::segmentation
