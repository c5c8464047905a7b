#pragma once

// The renderer's view of the camera: OpenCV's projection (as cv::projectPoints) inlined for
// speed, its inverse refined by Newton steps, and the guard region of the normalised image plane
// where the distortion polynomial is a proper (non-folding) map. Geometry outside the guard region
// is clipped away, so far-off-axis points never wrap back into the image through the polynomial.

#include <Eigen/Core>

#include "core/camera/pinhole_camera.h"

namespace avc::sim {

// Normalised-plane box (x = X/Z, y = Y/Z) holding the image plus a margin.
struct GuardBox {
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
};

class LensModel {
 public:
  // Throws std::invalid_argument when the intrinsics are unusable or the distortion folds over
  // inside the guard region.
  explicit LensModel(const camera::Intrinsics& intrinsics);

  const camera::Intrinsics& intrinsics() const { return intrinsics_; }
  bool distorted() const { return distorted_; }
  const GuardBox& guard() const { return guard_; }
  // Bound on how far (pixels) the image of the midpoint of a normalised-plane segment of squared
  // length d2 can stray from the midpoint of its imaged endpoints, inside the guard region:
  // (max |second derivative of the pixel map| / 8) d2, with a safety factor. 0 without distortion.
  double MidpointErrorBound(double d2) const { return midpoint_error_per_d2_ * d2; }

  // Distorted normalised coordinates, the same polynomial as cv::projectPoints.
  Eigen::Vector2d Distort(const Eigen::Vector2d& n) const {
    const double x = n.x(), y = n.y();
    const double r2 = x * x + y * y;
    const double radial = 1 + r2 * (k1_ + r2 * (k2_ + r2 * k3_));
    return {x * radial + 2 * p1_ * x * y + p2_ * (r2 + 2 * x * x),
            y * radial + p1_ * (r2 + 2 * y * y) + 2 * p2_ * x * y};
  }
  // Pixel (centres at integers) of normalised undistorted coordinates.
  Eigen::Vector2d PixelOf(const Eigen::Vector2d& n) const {
    const Eigen::Vector2d d = distorted_ ? Distort(n) : n;
    return {fx_ * d.x() + cx_, fy_ * d.y() + cy_};
  }
  // Normalised undistorted coordinates of a pixel by Newton's method from guess (the closer, the
  // fewer steps), to ~1e-6 px. Exact without distortion.
  Eigen::Vector2d NormalisedOf(const Eigen::Vector2d& pixel, const Eigen::Vector2d& guess) const;
  // Same, starting from the undistorted pinhole coordinates.
  Eigen::Vector2d NormalisedOf(const Eigen::Vector2d& pixel) const;

 private:
  // Jacobian of Distort at n.
  Eigen::Matrix2d DistortJacobian(const Eigen::Vector2d& n) const;
  // Solves Distort(n) = target by Newton's method from n.
  Eigen::Vector2d Refine(const Eigen::Vector2d& target, Eigen::Vector2d n) const;
  void ComputeGuard();
  void ComputeMidpointBound();

  camera::Intrinsics intrinsics_;
  bool distorted_ = false;
  double fx_, fy_, cx_, cy_, k1_, k2_, p1_, p2_, k3_;
  GuardBox guard_;
  double midpoint_error_per_d2_ = 0;
};

}  // namespace avc::sim
