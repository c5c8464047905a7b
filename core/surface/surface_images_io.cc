#include "core/surface/surface_images_io.h"

#include <fmt/format.h>

#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "core/camera/camera_io.h"

namespace avc::surface {
namespace {

// Colours are only compared, never located finely: a large image is decoded reduced so that
// at most about this many pixels remain (a real cell's 18-megapixel views: 2.2 megapixels,
// 6.7 MB each instead of 54).
constexpr double kMaxColourPixels = 2.5e6;

// folder/images/<stem>.jpg, the undistorted colour image the builder writes beside the mask,
// decoded reduced when large; empty when there is none. Throws std::runtime_error naming the
// file when it cannot be read or its size is not its camera's.
cv::Mat ReadColourImage(const std::filesystem::path& folder, const camera::NamedCamera& named) {
  std::filesystem::path file = folder / "images" / std::filesystem::path(named.name).filename();
  file.replace_extension(".jpg");
  if (!std::filesystem::is_regular_file(file)) return {};
  const camera::Intrinsics& k = named.camera.intrinsics;
  const double pixels = static_cast<double>(k.width) * static_cast<double>(k.height);
  int reduction = 1;
  while (reduction < 8 && pixels / (reduction * reduction) > kMaxColourPixels) reduction *= 2;
  const int flags = reduction == 8   ? cv::IMREAD_REDUCED_COLOR_8
                    : reduction == 4 ? cv::IMREAD_REDUCED_COLOR_4
                    : reduction == 2 ? cv::IMREAD_REDUCED_COLOR_2
                                     : cv::IMREAD_COLOR;
  cv::Mat image = cv::imread(file.string(), flags);
  if (image.empty()) {
    throw std::runtime_error(fmt::format("{}: not a readable image", file.string()));
  }
  if (ColourImageReduction(image, k) != reduction) {
    throw std::runtime_error(fmt::format("{}: {}x{} pixels, but its camera is {}x{}", file.string(),
                                         image.cols * reduction, image.rows * reduction, k.width,
                                         k.height));
  }
  return image;
}

}  // namespace

SurfaceImages ReadSurfaceImages(const std::filesystem::path& folder) {
  SurfaceImages images;
  const std::filesystem::path cameras_file = folder / "cameras.json";
  const std::filesystem::path masks = folder / "masks";
  if (!std::filesystem::is_regular_file(cameras_file) || !std::filesystem::is_directory(masks)) {
    return images;
  }
  for (const camera::NamedCamera& named : camera::ReadCamerasJson(cameras_file)) {
    std::filesystem::path mask_file = masks / std::filesystem::path(named.name).filename();
    mask_file.replace_extension(".png");
    if (!std::filesystem::is_regular_file(mask_file)) continue;
    cv::Mat mask = cv::imread(mask_file.string(), cv::IMREAD_GRAYSCALE);
    if (mask.empty()) {
      throw std::runtime_error(fmt::format("{}: not a readable image", mask_file.string()));
    }
    const camera::Intrinsics& k = named.camera.intrinsics;
    if (mask.cols != k.width || mask.rows != k.height) {
      throw std::runtime_error(fmt::format("{}: {}x{} pixels, but its camera in {} is {}x{}",
                                           mask_file.string(), mask.cols, mask.rows,
                                           cameras_file.string(), k.width, k.height));
    }
    images.views.push_back(
        {named.name, named.camera, std::move(mask), ReadColourImage(folder, named)});
  }
  return images;
}

SurfaceImages SurfaceImagesOf(const dataset::ViewSet& set) {
  SurfaceImages images;
  for (const dataset::View& view : set.views) {
    if (!view.mask.empty()) {
      images.views.push_back({view.name, view.camera, view.mask, view.image});
    }
  }
  return images;
}

}  // namespace avc::surface
