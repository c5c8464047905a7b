#include "core/mvs/plane_sweep/sweep_views.h"

#include <fmt/format.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "core/dataset/view_transforms.h"

namespace avc::mvs {
namespace {

std::string Describe(const std::vector<dataset::View>& views, size_t i) {
  return fmt::format("view {} ('{}')", i, views[i].name);
}

}  // namespace

void ValidateSweepInputs(const std::vector<dataset::View>& views) {
  if (views.size() < 2) {
    throw std::invalid_argument(
        fmt::format("plane sweep needs at least 2 views, got {}", views.size()));
  }
  for (size_t i = 0; i < views.size(); ++i) {
    const dataset::View& view = views[i];
    const camera::Intrinsics& k = view.camera.intrinsics;
    if (view.image.empty()) {
      throw std::invalid_argument(Describe(views, i) + ": image is empty");
    }
    if (view.image.type() != CV_8UC3) {
      throw std::invalid_argument(Describe(views, i) + ": image is not 8-bit 3-channel (BGR)");
    }
    if (const std::string problem = k.Validate(); !problem.empty()) {
      throw std::invalid_argument(Describe(views, i) + ": camera intrinsics: " + problem);
    }
    if (view.image.cols != k.width || view.image.rows != k.height) {
      throw std::invalid_argument(fmt::format("{}: image is {}x{} but its camera is {}x{}",
                                              Describe(views, i), view.image.cols, view.image.rows,
                                              k.width, k.height));
    }
    if (k.HasDistortion()) {
      throw std::invalid_argument(Describe(views, i) +
                                  ": camera has lens distortion; undistort the views first "
                                  "(dataset::Undistort)");
    }
    if (!view.camera.T_cam_world.matrix().allFinite()) {
      throw std::invalid_argument(Describe(views, i) + ": camera pose T_cam_world is not finite");
    }
    if (!view.mask.empty()) {
      if (view.mask.type() != CV_8UC1 || view.mask.size() != view.image.size()) {
        throw std::invalid_argument(Describe(views, i) + ": mask is not CV_8UC1 of the image size");
      }
      if (cv::countNonZero(view.mask) == 0) {
        throw std::invalid_argument(Describe(views, i) + ": mask has no plant pixels");
      }
    }
  }
}

int ChooseSweepLevel(const std::vector<dataset::View>& views, int requested) {
  if (requested >= 0) return requested;
  int longest = 0;
  for (const dataset::View& view : views) {
    longest = std::max({longest, view.image.cols, view.image.rows});
  }
  int level = 0;
  while ((longest >> level) > 800) ++level;
  return level;
}

std::vector<SweepView> PrepareSweepViews(const std::vector<dataset::View>& views, int level) {
  std::vector<SweepView> prepared(views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    const dataset::View scaled = dataset::AtPyramidLevel(views[i], level);
    SweepView& out = prepared[i];
    out.camera = scaled.camera;
    out.colour = scaled.image;
    cv::Mat grey8;
    cv::cvtColor(scaled.image, grey8, cv::COLOR_BGR2GRAY);
    grey8.convertTo(out.grey, CV_32F, 1.0 / 255.0);
    out.mask =
        scaled.mask.empty() ? cv::Mat(scaled.image.size(), CV_8UC1, cv::Scalar(255)) : scaled.mask;
  }
  return prepared;
}

}  // namespace avc::mvs
