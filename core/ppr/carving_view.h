#pragma once

// One view as carving uses it: a distortion-free camera and a label image (background, plant,
// not seen), plus the per-voxel-footprint test that casts the view's vote.

#include <opencv2/core/mat.hpp>
#include <string>

#include "core/camera/pinhole_camera.h"
#include "core/ppr/proxy_cell.h"

namespace avc::ppr {

enum PixelLabel : uint8_t { kBackgroundPixel = 0, kPlantPixel = 1, kUnseenPixel = 2 };

struct CarvingView {
  std::string name;
  camera::Camera camera;    // distortion removed
  cv::Mat labels;           // CV_8UC1 PixelLabel, camera image size
  bool has_unseen = false;  // some pixels inside the image are kUnseenPixel (after undistortion)
};

// Checks camera and mask (throws std::invalid_argument naming `name` and the bad field) and
// removes lens distortion by resampling the mask; pixels that no real pixel maps to become
// kUnseenPixel. Non-zero mask pixels are plant.
CarvingView PrepareCarvingView(const camera::Camera& camera, const cv::Mat& mask,
                               const std::string& name);

// What one view says about a whole cell.
enum class Footprint : uint8_t {
  kNoVote,      // outside the image, behind the camera, or (for a voxel) unclear
  kBackground,  // every pixel of the footprint is background
  kPlant,       // (cell) every pixel is plant; (voxel) at least one pixel is plant
  kMixed,       // a cell whose descendants vote differently: split it
};

// The footprint of a cell is the bounding rectangle of its 8 projected corners, taken as every
// pixel whose square it touches; a child's footprint lies inside its parent's, so a uniform
// verdict on a cell holds for every voxel in it.
class FootprintTest {
 public:
  FootprintTest(const CarvingView& view, double voxel_size);
  Footprint Classify(const ProxyCell& cell) const;

 private:
  int64_t RectSum(const cv::Mat& integral, int i0, int j0, int i1, int j1) const;

  Eigen::Matrix3d rotation_;
  Eigen::Vector3d translation_;
  double fx_, fy_, cx_, cy_;
  int width_, height_;
  double voxel_size_;
  cv::Mat plant_integral_;  // CV_32S sums of plant pixels
  cv::Mat seen_integral_;   // CV_32S sums of seen pixels; empty when every pixel is seen
};

}  // namespace avc::ppr
