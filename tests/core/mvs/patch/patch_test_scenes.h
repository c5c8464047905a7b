#pragma once

// Inputs for the patch MVS tests and the measurement program: the Middlebury dino with the
// README's silhouette recipe, a visual-hull proxy from masks, a textured plane rendered
// analytically, and a small simulated plant scan with masks from its label images.

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/dataset/view.h"
#include "core/geometry/mesh.h"
#include "core/mvs/mvs_bounds.h"
#include "core/mvs/mvs_points.h"

namespace avc::mvs::testing {

// The dino's silhouette: grey > 0.19, dilated 10 px, eroded 7 px (disc elements).
cv::Mat DinoSilhouette(const cv::Mat& bgr);

// Voxels of [lo, hi] (edge `voxel`) whose centre lies inside the mask of every view that sees
// it, allowing `misses` views to disagree; views whose image does not contain the centre do
// not vote.
MvsBounds VisualHull(const std::vector<dataset::View>& views, const Eigen::Vector3d& lo,
                     const Eigen::Vector3d& hi, double voxel, int misses = 1);

// Fraction of points that project inside silhouettes[j] for every j in their view list
// (outside the image counts as outside).
double InsideFraction(const MvsPoints& points, const std::vector<dataset::View>& views,
                      const std::vector<cv::Mat>& silhouettes);

// `count` cameras on a cone above the plane z = 0 at `distance`, looking at the origin, each
// seeing a seeded band-limited random texture of side `side` metres centred at the origin.
std::vector<dataset::View> TexturedPlaneViews(int count, int width, int height, double distance,
                                              double side, uint32_t seed);

// A rendered plant scan: views with masks (label != 0), the ground truth and its bounds.
struct SimScan {
  std::vector<dataset::View> views;
  geometry::Mesh ground_truth;
  Eigen::Vector3d lo, hi;
  std::vector<std::array<double, 5>> raw_distortion;  // per view, before Undistort
};
SimScan RenderScan(const std::filesystem::path& dir, int preset, int views, int width, int height);

}  // namespace avc::mvs::testing
