#pragma once

// A cell's colour model for Phase 2 with images (paper §4: the level set grows where the views'
// colours agree with the cell's colour model). The model is the chromaticity (r and g over
// r + g + b, so that shading and exposure cancel) of the colours of the cell's points, and the
// spread they show; a pixel agrees when its chromaticity lies within the tolerance of the mean.
// Pixels too dark to have a chromaticity agree: they say nothing about the colour.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <vector>

namespace avc::surface {

struct ColourModelOptions {
  // A pixel agrees within tolerance_factor times the points' RMS chromaticity distance from
  // their mean, but never less than min_tolerance (a uniformly coloured leaf's points still
  // differ by the views' lighting and the camera's noise).
  double tolerance_factor = 3.0;
  double min_tolerance = 0.03;
  int min_colours = 3;  // fewer usable colours: no model
};

class ColourModel {
 public:
  // rgb: the points' colours. nullopt when fewer than min_colours are bright enough.
  static std::optional<ColourModel> Fit(const std::vector<Eigen::Matrix<uint8_t, 3, 1>>& rgb,
                                        const ColourModelOptions& options = {});

  bool Agrees(const cv::Vec3b& bgr) const;

  const Eigen::Vector2f& mean() const { return mean_; }
  float tolerance() const { return tolerance_; }

 private:
  ColourModel(const Eigen::Vector2f& mean, float tolerance) : mean_(mean), tolerance_(tolerance) {}

  Eigen::Vector2f mean_;
  float tolerance_;
};

}  // namespace avc::surface
