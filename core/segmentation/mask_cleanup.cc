#include "core/segmentation/mask_cleanup.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace avc::segmentation {

cv::Mat CleanMask(const cv::Mat& mask, const CleanupOptions& options) {
  if (mask.empty() || mask.type() != CV_8UC1) {
    throw std::invalid_argument("CleanMask: mask must be a non-empty CV_8UC1 image");
  }
  cv::Mat binary = mask != 0;
  if (options.close_radius_px > 0) {
    const int size = 2 * options.close_radius_px + 1;
    const cv::Mat disc = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size));
    cv::morphologyEx(binary, binary, cv::MORPH_CLOSE, disc);
  }

  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(binary, labels, stats, centroids, 8, CV_32S);
  int largest = 0;
  for (int i = 1; i < count; ++i) largest = std::max(largest, stats.at<int>(i, cv::CC_STAT_AREA));
  const double min_area =
      std::max(options.min_component_fraction * largest,
               options.min_component_image_fraction * static_cast<double>(mask.total()));
  std::vector<uint8_t> keep(static_cast<size_t>(count), 0);
  for (int i = 1; i < count; ++i) {
    keep[static_cast<size_t>(i)] = stats.at<int>(i, cv::CC_STAT_AREA) >= min_area ? 255 : 0;
  }
  cv::Mat cleaned(mask.size(), CV_8UC1);
  for (int y = 0; y < mask.rows; ++y) {
    const int* in = labels.ptr<int>(y);
    uint8_t* out = cleaned.ptr<uint8_t>(y);
    for (int x = 0; x < mask.cols; ++x) out[x] = keep[static_cast<size_t>(in[x])];
  }
  return cleaned;
}

}  // namespace avc::segmentation
