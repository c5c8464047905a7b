#include "bench/real/reference_silhouette.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::bench {
namespace {

// Pixels of `mask` whose distance to the nearest non-zero pixel of `target` exceeds tolerance.
cv::Mat FartherThan(const cv::Mat& target, double tolerance_px) {
  cv::Mat outside = target == 0;
  cv::Mat distance;
  cv::distanceTransform(outside, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance > tolerance_px;
}

double Fraction(int part, int whole) { return whole == 0 ? 0.0 : double(part) / whole; }

}  // namespace

cv::Mat ReferenceSilhouette(const geometry::Mesh& mesh, const camera::Camera& camera) {
  const auto& k = camera.intrinsics;
  cv::Mat silhouette = cv::Mat::zeros(k.height, k.width, CV_8UC1);
  std::vector<std::optional<Eigen::Vector2d>> pixels;
  pixels.reserve(mesh.vertices.size());
  for (const Eigen::Vector3f& vertex : mesh.vertices) {
    pixels.push_back(camera.Project(vertex.cast<double>()));
  }
  for (const Eigen::Vector3i& face : mesh.faces) {
    cv::Point corners[3];
    bool visible = true;
    for (int c = 0; c < 3 && visible; ++c) {
      const auto& pixel = pixels[static_cast<size_t>(face[c])];
      visible = pixel.has_value();
      if (visible) corners[c] = cv::Point(cvRound(pixel->x()), cvRound(pixel->y()));
    }
    if (visible) cv::fillConvexPoly(silhouette, corners, 3, cv::Scalar(255));
  }
  return silhouette;
}

MaskAgainstReference CompareMask(const cv::Mat& mask, const cv::Mat& reference,
                                 double tolerance_px) {
  if (mask.size() != reference.size() || mask.type() != CV_8UC1 || reference.type() != CV_8UC1) {
    throw std::invalid_argument("CompareMask: mask and reference must be CV_8UC1 of one size");
  }
  const cv::Mat plant = mask > 0;
  const cv::Mat truth = reference > 0;
  MaskAgainstReference result;
  const int plant_pixels = cv::countNonZero(plant);
  const int truth_pixels = cv::countNonZero(truth);
  result.plant_fraction = Fraction(plant_pixels, static_cast<int>(mask.total()));
  result.off_reference =
      Fraction(cv::countNonZero(plant & FartherThan(truth, tolerance_px)), plant_pixels);
  result.reference_covered = Fraction(
      truth_pixels - cv::countNonZero(truth & FartherThan(plant, tolerance_px)), truth_pixels);
  return result;
}

}  // namespace avc::bench
