#pragma once

// Fronto-parallel plane homographies from a reference view into another view, and warping the
// other view's grey image through them (the inner loop of the sweep).

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/types.hpp>

#include "core/camera/pinhole_camera.h"
#include "core/mvs/plane_sweep/sweep_views.h"

namespace avc::mvs {

// Reference pixel (x, y, 1) images in the other view at a x̃ + b w for the fronto-parallel
// plane at inverse depth w (the plane homography's third column is the only part that moves).
struct HomographyBasis {
  Eigen::Matrix3d a;
  Eigen::Vector3d b;

  Eigen::Matrix3d AtInverseDepth(double w) const {
    Eigen::Matrix3d h = a;
    h.col(2) += b * w;
    return h;
  }
};

HomographyBasis MakeHomographyBasis(const camera::Camera& reference, const camera::Camera& other);

// Other view's grey values at the homography images of the region's reference pixels
// (bilinear), row-major region.width x region.height; `inside` is 0 where a pixel maps outside
// the other image (its value is then 0).
void WarpByPlane(const SweepView& other, const Eigen::Matrix3d& h, const cv::Rect& region,
                 float* warped, uint8_t* inside);

}  // namespace avc::mvs
