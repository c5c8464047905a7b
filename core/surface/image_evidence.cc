#include "core/surface/image_evidence.h"

#include <fmt/format.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::surface {

ImageEvidence::ImageEvidence(const SurfaceImages& images, const ImageGrowthOptions& options)
    : min_plant_views_(options.min_plant_views),
      min_background_views_(options.min_background_views) {
  for (const EvidenceView& view : images.views) {
    const camera::Intrinsics& k = view.camera.intrinsics;
    if (view.mask.type() != CV_8UC1 || view.mask.cols != k.width || view.mask.rows != k.height) {
      throw std::invalid_argument(fmt::format(
          "image growth: the mask of view '{}' is not an 8-bit single-channel {}x{} image",
          view.name, k.width, k.height));
    }
    PreparedView prepared{view.camera, view.mask, cv::Mat()};
    // For each background pixel, its distance to the nearest plant pixel.
    cv::Mat background = view.mask == 0;
    cv::Mat distance;
    cv::distanceTransform(background, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    prepared.background = distance > options.edge_tolerance_px;
    views_.push_back(std::move(prepared));
  }
}

NodeVerdict ImageEvidence::Judge(const Eigen::Vector3d& point) const {
  int plant = 0;
  int background = 0;
  for (const PreparedView& view : views_) {
    const std::optional<Eigen::Vector2d> pixel = view.camera.Project(point);
    if (!pixel) continue;
    const double x = std::round(pixel->x());
    const double y = std::round(pixel->y());
    if (!(x >= 0.0 && y >= 0.0 && x < view.mask.cols && y < view.mask.rows)) continue;
    const int column = static_cast<int>(x);
    const int row = static_cast<int>(y);
    if (view.mask.at<uint8_t>(row, column) != 0) {
      ++plant;
    } else if (view.background.at<uint8_t>(row, column) != 0) {
      if (++background >= min_background_views_) return NodeVerdict::kBackground;
    }
  }
  return plant >= min_plant_views_ ? NodeVerdict::kPlant : NodeVerdict::kUnknown;
}

}  // namespace avc::surface
