#pragma once

// Scenes and measurements shared by the plane-sweep tests: a textured plane seen by a small
// fan of cameras, voxel bounds (a box, a visual hull), the Middlebury silhouette recipe.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/dataset/view.h"
#include "core/mvs/mvs_bounds.h"
#include "core/mvs/mvs_points.h"

namespace avc::mvs::sweep_test {

// A random texture on the plane through the origin with normal (0, sin tilt, cos tilt), seen by
// five 320x240 cameras 0.4 m away (one straight along -z, four 20 degrees off); masks are where
// the texture lands.
struct TexturedPlane {
  std::vector<dataset::View> views;
  Eigen::Vector3d normal;
  MvsBounds bounds;  // 4 mm voxels the plane passes through
};
TexturedPlane MakeTexturedPlane(double tilt, uint32_t seed);

// Every voxel centre of the box on a grid of `voxel` metres.
MvsBounds BoxBounds(const Eigen::Vector3d& min, const Eigen::Vector3d& max, double voxel);

// The box's voxels whose centres fall outside at most `misses` of the masks they project into.
MvsBounds VisualHull(const std::vector<dataset::View>& views, const Eigen::Vector3d& min,
                     const Eigen::Vector3d& max, double voxel, int misses);

// Middlebury's silhouette: grey > 0.19, dilated 10 px, eroded 7 px (disc elements).
cv::Mat MiddleburySilhouette(const cv::Mat& bgr);

// Fraction of points that project inside the silhouette of every view that sees them.
double InsideSilhouetteFraction(const MvsPoints& points, const std::vector<dataset::View>& views,
                                const std::vector<cv::Mat>& silhouettes);

// Fraction of points inside the box.
double InsideBoxFraction(const MvsPoints& points, const Eigen::Vector3d& min,
                         const Eigen::Vector3d& max);

}  // namespace avc::mvs::sweep_test
