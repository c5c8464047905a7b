#include "core/surface/image_evidence.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::surface {

int ColourImageReduction(const cv::Mat& image, const camera::Intrinsics& k) {
  if (image.type() != CV_8UC3) return 0;
  for (int reduction : {1, 2, 4, 8}) {
    if (image.cols == (k.width + reduction - 1) / reduction &&
        image.rows == (k.height + reduction - 1) / reduction) {
      return reduction;
    }
  }
  return 0;
}

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
    const int reduction = view.image.empty() ? 1 : ColourImageReduction(view.image, k);
    if (reduction == 0) {
      throw std::invalid_argument(fmt::format(
          "image growth: the image of view '{}' is not an 8-bit colour {}x{} image (or that "
          "size reduced 2, 4 or 8 times)",
          view.name, k.width, k.height));
    }
    // For each background pixel, its distance to the nearest plant pixel.
    cv::Mat distance;
    cv::distanceTransform(view.mask == 0, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    cv::Mat says(view.mask.size(), CV_8UC1, cv::Scalar(kNearEdge));
    says.setTo(kClearBackground, distance > options.edge_tolerance_px);
    says.setTo(kPlant, view.mask != 0);
    views_.push_back({view.camera, std::move(says), view.image, reduction});
  }
}

NodeVerdict ImageEvidence::Judge(const Eigen::Vector3d& point, const ColourModel* colour) const {
  int plant = 0;
  int agreeing = 0;
  int background = 0;
  for (const PreparedView& view : views_) {
    const std::optional<Eigen::Vector2d> pixel = view.camera.Project(point);
    if (!pixel) continue;
    const double x = std::round(pixel->x());
    const double y = std::round(pixel->y());
    if (!(x >= 0.0 && y >= 0.0 && x < view.says.cols && y < view.says.rows)) continue;
    const int row = static_cast<int>(y);
    const int column = static_cast<int>(x);
    const uint8_t says = view.says.at<uint8_t>(row, column);
    if (says == kPlant) {
      ++plant;
      if (colour == nullptr || view.image.empty() ||
          colour->Agrees(
              view.image.at<cv::Vec3b>(std::min(row / view.reduction, view.image.rows - 1),
                                       std::min(column / view.reduction, view.image.cols - 1)))) {
        ++agreeing;
      }
    } else if (says == kClearBackground && ++background >= min_background_views_) {
      return NodeVerdict::kBackground;
    }
  }
  if (plant < min_plant_views_) return NodeVerdict::kUnknown;
  return agreeing >= min_plant_views_ && 2 * agreeing >= plant ? NodeVerdict::kPlant
                                                               : NodeVerdict::kOtherColour;
}

}  // namespace avc::surface
