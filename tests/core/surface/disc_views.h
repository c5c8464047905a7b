#pragma once

// Views of a flat round leaf and their plant masks, for the tests of Phase 2 with images: a
// disc in a horizontal plane seen from sixteen cameras above it, its masks made by casting each
// pixel's ray onto the plane. WriteSurfaceImages lays them out as the builder writes a
// reconstruction folder (cameras.json, masks/<name>.png).

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/camera/camera_io.h"
#include "core/surface/image_evidence.h"
#include "tests/core/eval/test_scenes.h"

namespace avc::surface {

inline camera::Camera LookingAt(const Eigen::Vector3d& centre, const Eigen::Vector3d& target) {
  return eval::test::LookAt(centre, target, Eigen::Vector3d::UnitZ());
}

// The mask of a disc of the given radius in the plane z = height about the z axis, by ray
// casting.
inline cv::Mat DiscMask(const camera::Camera& camera, double radius, double height = 0.0) {
  const camera::Intrinsics& k = camera.intrinsics;
  cv::Mat mask(k.height, k.width, CV_8UC1, cv::Scalar(0));
  eval::test::ForEachPlaneHit(camera, height, [&](int row, int column, const Eigen::Vector3d& hit) {
    if (hit.head<2>().norm() <= radius) mask.at<uint8_t>(row, column) = 255;
  });
  return mask;
}

// The colours of the disc's plane seen by a camera: `inner` within radius of the z axis,
// `outer` beyond it (BGR).
inline cv::Mat TwoColourPlane(const camera::Camera& camera, double radius, const cv::Vec3b& inner,
                              const cv::Vec3b& outer, double height = 0.0) {
  const camera::Intrinsics& k = camera.intrinsics;
  cv::Mat image(k.height, k.width, CV_8UC3, cv::Scalar(128, 128, 128));
  eval::test::ForEachPlaneHit(camera, height, [&](int row, int column, const Eigen::Vector3d& hit) {
    image.at<cv::Vec3b>(row, column) = hit.head<2>().norm() <= radius ? inner : outer;
  });
  return image;
}

// Sixteen views round the disc from above, at 45 and 70 degrees elevation, 0.3 m away.
inline SurfaceImages ViewsOfDisc(double mask_radius, double height = 0.0) {
  SurfaceImages images;
  for (int k = 0; k < 16; ++k) {
    const double elevation = (k < 12 ? 45.0 : 70.0) * std::numbers::pi / 180.0;
    const double azimuth = 2.0 * std::numbers::pi * k / (k < 12 ? 12.0 : 4.0);
    const Eigen::Vector3d centre =
        0.3 * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                              std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    const Eigen::Vector3d target(0.0, 0.0, height);
    const camera::Camera camera = LookingAt(target + centre, target);
    images.views.push_back(
        {"view_" + std::to_string(k), camera, DiscMask(camera, mask_radius, height), cv::Mat()});
  }
  return images;
}

inline void WriteSurfaceImages(const std::filesystem::path& folder, const SurfaceImages& images) {
  std::filesystem::create_directories(folder / "masks");
  std::vector<camera::NamedCamera> cameras;
  for (const EvidenceView& view : images.views) {
    cameras.push_back({view.name + ".jpg", view.camera});
    cv::imwrite((folder / "masks" / (view.name + ".png")).string(), view.mask);
  }
  camera::WriteCamerasJson(folder / "cameras.json", cameras);
}

}  // namespace avc::surface
