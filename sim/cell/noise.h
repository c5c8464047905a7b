#pragma once

// Measurement noise of the simulated devices, every model seeded and bit-for-bit deterministic:
// joint encoders, the turntable's angle and the camera's pixels and exposure.

#include <cstdint>
#include <numbers>
#include <opencv2/core.hpp>
#include <string>

#include "core/kinematics/dh_parameters.h"
#include "sim/cell/random.h"

namespace avc::sim {

struct EncoderNoise {
  double sigma_rad = 1e-5;  // per joint and reading
};

// Joint readings: the true joints plus independent Gaussian noise per joint and reading.
class JointEncoders {
 public:
  JointEncoders(const EncoderNoise& noise, uint64_t seed);
  kinematics::JointVector Read(const kinematics::JointVector& true_q);

 private:
  EncoderNoise noise_;
  DeterministicRandom random_;
};

struct TurntableNoise {
  double step_rad = 0.1 * std::numbers::pi / 180;    // the LT360 resolves tenths of a degree
  double offset_rad = 0;                             // systematic: constant angle error
  double scale_error = 0;                            // systematic: relative error of the angle
  double sigma_rad = 0.05 * std::numbers::pi / 180;  // random, per move

  std::string Validate() const;
};

struct TurntableMove {
  double commanded_rad = 0;  // the request rounded to the table's step; what the table reports
  double true_rad = 0;       // where the table really is
};

// `angle` rounded to the nearest multiple of `step` (halves away from zero).
double QuantiseAngle(double angle, double step);

// The turntable's true angle for each commanded move:
// true = commanded * (1 + scale_error) + offset + N(0, sigma).
class TurntableModel {
 public:
  TurntableModel(const TurntableNoise& noise, uint64_t seed);  // throws on invalid noise
  TurntableMove MoveTo(double requested_rad);                  // throws on a non-finite request

 private:
  TurntableNoise noise_;
  DeterministicRandom random_;
};

// Sensor noise on 8-bit images, in grey levels: a pixel of (gain-scaled) level s gets Gaussian
// noise of variance read_sigma^2 + shot_variance_per_level * s, the photon-like part growing with
// the signal. The per-image exposure gain is exp(N(0, gain_log_sigma)), so brightness changes
// from image to image as with an auto-exposure camera (the median gain is 1).
struct ImageNoise {
  double read_sigma = 1.5;
  double shot_variance_per_level = 0.03;
  double gain_log_sigma = 0.03;

  std::string Validate() const;
};

// The exposure gain ApplyImageNoise uses for `seed`.
double ExposureGain(const ImageNoise& noise, uint64_t seed);

// Applies exposure gain and pixel noise in place (rounded, saturated to 0..255) to an 8-bit image
// with any number of channels. Throws std::invalid_argument for an empty or non-8-bit image or
// invalid noise settings.
void ApplyImageNoise(cv::Mat& image, const ImageNoise& noise, uint64_t seed);

}  // namespace avc::sim
