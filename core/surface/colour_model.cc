#include "core/surface/colour_model.h"

#include <algorithm>
#include <cmath>

namespace avc::surface {
namespace {

// Below this sum of the three channels (of 765) a colour is too dark for its chromaticity to
// mean much: the camera's noise decides it.
constexpr int kMinBrightness = 45;

std::optional<Eigen::Vector2f> Chromaticity(int red, int green, int blue) {
  const int sum = red + green + blue;
  if (sum < kMinBrightness) return std::nullopt;
  return Eigen::Vector2f(static_cast<float>(red) / sum, static_cast<float>(green) / sum);
}

}  // namespace

std::optional<ColourModel> ColourModel::Fit(const std::vector<Eigen::Matrix<uint8_t, 3, 1>>& rgb,
                                            const ColourModelOptions& options) {
  std::vector<Eigen::Vector2f> chroma;
  chroma.reserve(rgb.size());
  for (const Eigen::Matrix<uint8_t, 3, 1>& c : rgb) {
    if (const auto value = Chromaticity(c[0], c[1], c[2])) chroma.push_back(*value);
  }
  if (chroma.empty() || static_cast<int>(chroma.size()) < options.min_colours) return std::nullopt;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2f& c : chroma) sum += c.cast<double>();
  const Eigen::Vector2d mean = sum / static_cast<double>(chroma.size());
  double squared = 0.0;
  for (const Eigen::Vector2f& c : chroma) squared += (c.cast<double>() - mean).squaredNorm();
  const double rms = std::sqrt(squared / static_cast<double>(chroma.size()));
  const double tolerance = std::max(options.min_tolerance, options.tolerance_factor * rms);
  return ColourModel(mean.cast<float>(), static_cast<float>(tolerance));
}

bool ColourModel::Agrees(const cv::Vec3b& bgr) const {
  const std::optional<Eigen::Vector2f> chroma = Chromaticity(bgr[2], bgr[1], bgr[0]);
  return !chroma || (*chroma - mean_).norm() <= tolerance_;
}

}  // namespace avc::surface
