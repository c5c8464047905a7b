#include "sim/cell/noise.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace avc::sim {
namespace {

bool NonNegative(double value) { return std::isfinite(value) && value >= 0; }

}  // namespace

JointEncoders::JointEncoders(const EncoderNoise& noise, uint64_t seed)
    : noise_(noise), random_(seed) {
  if (!NonNegative(noise.sigma_rad)) {
    throw std::invalid_argument(fmt::format(
        "JointEncoders: sigma_rad = {} must be finite and non-negative", noise.sigma_rad));
  }
}

kinematics::JointVector JointEncoders::Read(const kinematics::JointVector& true_q) {
  if (!true_q.allFinite())
    throw std::invalid_argument("JointEncoders::Read: joints are not finite");
  kinematics::JointVector reading;
  for (int i = 0; i < 6; ++i) reading[i] = true_q[i] + noise_.sigma_rad * random_.Normal();
  return reading;
}

std::string TurntableNoise::Validate() const {
  if (!(std::isfinite(step_rad) && step_rad > 0)) {
    return fmt::format("turntable step_rad = {} must be positive", step_rad);
  }
  if (!std::isfinite(offset_rad)) return "turntable offset_rad is not finite";
  if (!(std::isfinite(scale_error) && std::abs(scale_error) < 0.5)) {
    return fmt::format("turntable scale_error = {} must be finite and below 0.5", scale_error);
  }
  if (!NonNegative(sigma_rad)) {
    return fmt::format("turntable sigma_rad = {} must be finite and non-negative", sigma_rad);
  }
  return {};
}

double QuantiseAngle(double angle, double step) { return std::round(angle / step) * step; }

TurntableModel::TurntableModel(const TurntableNoise& noise, uint64_t seed)
    : noise_(noise), random_(seed) {
  if (std::string error = noise.Validate(); !error.empty()) {
    throw std::invalid_argument("TurntableModel: " + error);
  }
}

TurntableMove TurntableModel::MoveTo(double requested_rad) {
  if (!std::isfinite(requested_rad)) {
    throw std::invalid_argument("TurntableModel::MoveTo: the requested angle is not finite");
  }
  TurntableMove move;
  move.commanded_rad = QuantiseAngle(requested_rad, noise_.step_rad);
  move.true_rad = move.commanded_rad * (1 + noise_.scale_error) + noise_.offset_rad +
                  noise_.sigma_rad * random_.Normal();
  return move;
}

std::string ImageNoise::Validate() const {
  if (!NonNegative(read_sigma))
    return fmt::format("image read_sigma = {} must be non-negative", read_sigma);
  if (!NonNegative(shot_variance_per_level)) {
    return fmt::format("image shot_variance_per_level = {} must be non-negative",
                       shot_variance_per_level);
  }
  if (!NonNegative(gain_log_sigma)) {
    return fmt::format("image gain_log_sigma = {} must be non-negative", gain_log_sigma);
  }
  return {};
}

double ExposureGain(const ImageNoise& noise, uint64_t seed) {
  DeterministicRandom random(seed);
  return std::exp(noise.gain_log_sigma * random.Normal());
}

void ApplyImageNoise(cv::Mat& image, const ImageNoise& noise, uint64_t seed) {
  if (std::string error = noise.Validate(); !error.empty()) {
    throw std::invalid_argument("ApplyImageNoise: " + error);
  }
  if (image.empty()) throw std::invalid_argument("ApplyImageNoise: the image is empty");
  if (image.depth() != CV_8U) {
    throw std::invalid_argument(fmt::format(
        "ApplyImageNoise: the image must have 8-bit channels, got OpenCV type {}", image.type()));
  }
  // The gain is the first draw of the same stream, so ExposureGain(seed) reports it.
  DeterministicRandom random(seed);
  const double gain = std::exp(noise.gain_log_sigma * random.Normal());
  const double read_variance = noise.read_sigma * noise.read_sigma;
  const int values_per_row = image.cols * image.channels();
  // Row by row in memory order: the result does not depend on how the image is strided.
  for (int row = 0; row < image.rows; ++row) {
    uint8_t* values = image.ptr<uint8_t>(row);
    for (int i = 0; i < values_per_row; ++i) {
      const double signal = gain * values[i];
      const double sigma = std::sqrt(read_variance + noise.shot_variance_per_level * signal);
      const double noisy = std::round(signal + sigma * random.Normal());
      values[i] = static_cast<uint8_t>(std::clamp(noisy, 0.0, 255.0));
    }
  }
}

}  // namespace avc::sim
