#include "sim/render/lens_model.h"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace avc::sim {
namespace {

// Pixels beyond the image border that the guard region still covers, so the clipped edges of
// partly visible triangles land outside the image.
constexpr double kGuardMarginPx = 8.0;
constexpr int kBorderSamplesPerSide = 256;
constexpr int kFoldCheckGrid = 65;
constexpr int kCurvatureGrid = 33;
// The curvature is sampled on a grid; between samples it may be a little larger.
constexpr double kCurvatureSafety = 2.0;

}  // namespace

LensModel::LensModel(const camera::Intrinsics& intrinsics) : intrinsics_(intrinsics) {
  const std::string problem = intrinsics.Validate();
  if (!problem.empty()) throw std::invalid_argument("camera intrinsics: " + problem);
  distorted_ = intrinsics.HasDistortion();
  fx_ = intrinsics.fx;
  fy_ = intrinsics.fy;
  cx_ = intrinsics.cx;
  cy_ = intrinsics.cy;
  k1_ = intrinsics.distortion[0];
  k2_ = intrinsics.distortion[1];
  p1_ = intrinsics.distortion[2];
  p2_ = intrinsics.distortion[3];
  k3_ = intrinsics.distortion[4];
  ComputeGuard();
  ComputeMidpointBound();
}

Eigen::Matrix2d LensModel::DistortJacobian(const Eigen::Vector2d& n) const {
  const double x = n.x(), y = n.y();
  const double r2 = x * x + y * y;
  const double radial = 1 + r2 * (k1_ + r2 * (k2_ + r2 * k3_));
  const double radial_d = k1_ + r2 * (2 * k2_ + 3 * r2 * k3_);  // d radial / d r2
  Eigen::Matrix2d j;
  j(0, 0) = radial + 2 * x * x * radial_d + 2 * p1_ * y + 6 * p2_ * x;
  j(0, 1) = 2 * x * y * radial_d + 2 * p1_ * x + 2 * p2_ * y;
  j(1, 0) = j(0, 1);
  j(1, 1) = radial + 2 * y * y * radial_d + 6 * p1_ * y + 2 * p2_ * x;
  return j;
}

Eigen::Vector2d LensModel::Refine(const Eigen::Vector2d& target, Eigen::Vector2d n) const {
  // Newton converges quadratically: from a guess within a pixel, one or two steps reach the
  // tolerance (1e-9 of normalised coordinates, ~1e-6 px: depth to ~1e-9 relative).
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector2d residual = Distort(n) - target;
    if (!(residual.squaredNorm() > 1e-18)) break;
    const Eigen::Matrix2d j = DistortJacobian(n);
    const double det = j(0, 0) * j(1, 1) - j(0, 1) * j(1, 0);
    if (!(std::abs(det) > 1e-300)) break;
    n.x() -= (j(1, 1) * residual.x() - j(0, 1) * residual.y()) / det;
    n.y() -= (j(0, 0) * residual.y() - j(1, 0) * residual.x()) / det;
  }
  return n;
}

Eigen::Vector2d LensModel::NormalisedOf(const Eigen::Vector2d& pixel,
                                        const Eigen::Vector2d& guess) const {
  const Eigen::Vector2d target((pixel.x() - cx_) / fx_, (pixel.y() - cy_) / fy_);
  if (!distorted_) return target;
  return Refine(target, guess);
}

Eigen::Vector2d LensModel::NormalisedOf(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d target((pixel.x() - cx_) / fx_, (pixel.y() - cy_) / fy_);
  if (!distorted_) return target;
  return Refine(target, target);
}

void LensModel::ComputeGuard() {
  const double left = -0.5 - kGuardMarginPx, top = -0.5 - kGuardMarginPx;
  const double right = intrinsics_.width - 0.5 + kGuardMarginPx;
  const double bottom = intrinsics_.height - 0.5 + kGuardMarginPx;
  GuardBox box{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
               std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  auto include = [&](double u, double v) {
    const Eigen::Vector2d n = NormalisedOf({u, v});
    const Eigen::Vector2d back = PixelOf(n);
    if (!n.allFinite() || (back - Eigen::Vector2d(u, v)).norm() > 1e-6) {
      throw std::invalid_argument(fmt::format(
          "camera distortion cannot be inverted at pixel ({:.1f}, {:.1f}) near the image "
          "border: the k1 k2 p1 p2 k3 polynomial folds over inside the field of view",
          u, v));
    }
    box.x_min = std::min(box.x_min, n.x());
    box.x_max = std::max(box.x_max, n.x());
    box.y_min = std::min(box.y_min, n.y());
    box.y_max = std::max(box.y_max, n.y());
  };
  for (int i = 0; i <= kBorderSamplesPerSide; ++i) {
    const double t = static_cast<double>(i) / kBorderSamplesPerSide;
    include(left + t * (right - left), top);
    include(left + t * (right - left), bottom);
    include(left, top + t * (bottom - top));
    include(right, top + t * (bottom - top));
  }
  if (!distorted_) {
    guard_ = box;
    return;
  }
  // A little extra room where the polynomial allows it; never a region where it folds.
  for (double extra : {0.05, 0.02, 0.0}) {
    const double dx = extra * (box.x_max - box.x_min), dy = extra * (box.y_max - box.y_min);
    const GuardBox grown{box.x_min - dx, box.x_max + dx, box.y_min - dy, box.y_max + dy};
    bool folds = false;
    for (int i = 0; i < kFoldCheckGrid && !folds; ++i) {
      for (int j = 0; j < kFoldCheckGrid && !folds; ++j) {
        const double x = grown.x_min + (grown.x_max - grown.x_min) * i / (kFoldCheckGrid - 1);
        const double y = grown.y_min + (grown.y_max - grown.y_min) * j / (kFoldCheckGrid - 1);
        folds = !(DistortJacobian({x, y}).determinant() > 0);
      }
    }
    if (!folds) {
      guard_ = grown;
      return;
    }
  }
  throw std::invalid_argument(
      "camera distortion folds over (its Jacobian is not positive) inside the field of view; "
      "the k1 k2 p1 p2 k3 model is not usable for this image size");
}

}  // namespace avc::sim

namespace avc::sim {

void LensModel::ComputeMidpointBound() {
  if (!distorted_) return;
  // Second derivatives by central differences of the analytic Jacobian.
  constexpr double h = 1e-5;
  double worst = 0;
  for (int i = 0; i < kCurvatureGrid; ++i) {
    for (int j = 0; j < kCurvatureGrid; ++j) {
      const Eigen::Vector2d n(
          guard_.x_min + (guard_.x_max - guard_.x_min) * i / (kCurvatureGrid - 1),
          guard_.y_min + (guard_.y_max - guard_.y_min) * j / (kCurvatureGrid - 1));
      const Eigen::Matrix2d d_dx = (DistortJacobian(n + Eigen::Vector2d(h, 0)) -
                                    DistortJacobian(n - Eigen::Vector2d(h, 0))) /
                                   (2 * h);
      const Eigen::Matrix2d d_dy = (DistortJacobian(n + Eigen::Vector2d(0, h)) -
                                    DistortJacobian(n - Eigen::Vector2d(0, h))) /
                                   (2 * h);
      // |D''(d, d)| <= Frobenius norm of the second-derivative tensor for any unit d.
      worst = std::max(worst, std::sqrt(d_dx.squaredNorm() + d_dy.squaredNorm()));
    }
  }
  midpoint_error_per_d2_ = kCurvatureSafety * std::max(fx_, fy_) * worst / 8.0;
}

}  // namespace avc::sim
