#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "sim/cell/noise.h"
#include "sim/cell/random.h"

namespace avc::sim {
namespace {

struct Moments {
  double mean = 0;
  double std = 0;
};

Moments Measure(const std::vector<double>& values) {
  double sum = 0, sum_squares = 0;
  for (double v : values) sum += v;
  const double mean = sum / values.size();
  for (double v : values) sum_squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(sum_squares / (values.size() - 1))};
}

TEST(DeterministicRandom, EngineIsTheStandardOne) {
  // [rand.predef]: the 10000th output of a default-constructed mt19937_64.
  DeterministicRandom random(5489u);
  uint64_t value = 0;
  for (int i = 0; i < 10000; ++i) value = random.Bits();
  EXPECT_EQ(value, 9981545732273789042ull);
}

TEST(DeterministicRandom, NormalHasUnitMoments) {
  DeterministicRandom random(7);
  std::vector<double> values(200000);
  int within_one_sigma = 0;
  for (double& v : values) {
    v = random.Normal();
    if (std::abs(v) < 1) ++within_one_sigma;
  }
  const Moments moments = Measure(values);
  EXPECT_NEAR(moments.mean, 0.0, 0.01);  // standard error 0.0022
  EXPECT_NEAR(moments.std, 1.0, 0.01);
  EXPECT_NEAR(within_one_sigma / 200000.0, 0.6827, 0.005);
}

TEST(DeterministicRandom, UniformAndUnitVectorsAreInRange) {
  DeterministicRandom random(8);
  double smallest = 1, largest = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < 100000; ++i) {
    const double u = random.Uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    smallest = std::min(smallest, u);
    largest = std::max(largest, u);
    const Eigen::Vector3d direction = random.UnitVector();
    ASSERT_NEAR(direction.norm(), 1.0, 1e-15);
    sum += direction;
  }
  EXPECT_LT(smallest, 1e-4);
  EXPECT_GT(largest, 1 - 1e-4);
  EXPECT_LT((sum / 100000).norm(), 0.01);  // no preferred direction
}

TEST(DeterministicRandom, SameSeedSameSequence) {
  DeterministicRandom a(42), b(42), c(43);
  bool any_difference = false;
  for (int i = 0; i < 1000; ++i) {
    const double x = a.Normal();
    ASSERT_EQ(x, b.Normal());
    any_difference |= x != c.Normal();
  }
  EXPECT_TRUE(any_difference);
}

TEST(JointEncoders, ReadingsScatterWithTheConfiguredSigma) {
  JointEncoders encoders({.sigma_rad = 1e-5}, 3);
  kinematics::JointVector q;
  q << 0.1, -1.2, 1.5, -0.3, 2.0, -2.5;
  std::vector<std::vector<double>> errors(6);
  for (int i = 0; i < 20000; ++i) {
    const kinematics::JointVector reading = encoders.Read(q);
    for (int j = 0; j < 6; ++j) errors[j].push_back(reading[j] - q[j]);
  }
  for (int j = 0; j < 6; ++j) {
    const Moments moments = Measure(errors[j]);
    EXPECT_NEAR(moments.mean, 0.0, 4e-7) << "joint " << j + 1;  // 5.6 standard errors
    EXPECT_NEAR(moments.std, 1e-5, 3e-7) << "joint " << j + 1;
  }
  JointEncoders again({.sigma_rad = 1e-5}, 3);
  JointEncoders replay({.sigma_rad = 1e-5}, 3);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(again.Read(q), replay.Read(q));
  EXPECT_THROW(JointEncoders({.sigma_rad = -1}, 1), std::invalid_argument);
  EXPECT_THROW(again.Read(kinematics::JointVector::Constant(std::nan(""))), std::invalid_argument);
}

TEST(TurntableModel, CommandsAreQuantisedToTenthsOfADegree) {
  const double tenth = 0.1 * std::numbers::pi / 180;
  TurntableModel table({}, 5);
  DeterministicRandom requests(6);
  for (int i = 0; i < 1000; ++i) {
    const double requested = requests.Uniform(-2 * std::numbers::pi, 2 * std::numbers::pi);
    const TurntableMove move = table.MoveTo(requested);
    const double steps = move.commanded_rad / tenth;
    EXPECT_NEAR(steps, std::round(steps), 1e-9);
    EXPECT_LE(std::abs(move.commanded_rad - requested), tenth / 2 + 1e-15);
  }
  EXPECT_NEAR(QuantiseAngle(0.34 * std::numbers::pi / 180, tenth), 0.3 * std::numbers::pi / 180,
              1e-15);
  EXPECT_NEAR(QuantiseAngle(-0.36 * std::numbers::pi / 180, tenth), -0.4 * std::numbers::pi / 180,
              1e-15);
}

TEST(TurntableModel, TrueAngleHasTheConfiguredErrors) {
  TurntableNoise noise;
  noise.offset_rad = 2e-3;
  noise.scale_error = 1e-3;
  noise.sigma_rad = 5e-4;
  TurntableModel table(noise, 9);
  std::vector<double> errors;
  for (int i = 0; i < 20000; ++i) {
    const TurntableMove move = table.MoveTo(0.01 * (i % 600));
    errors.push_back(move.true_rad - move.commanded_rad * (1 + noise.scale_error) -
                     noise.offset_rad);
  }
  const Moments moments = Measure(errors);
  EXPECT_NEAR(moments.mean, 0.0, 2e-5);
  EXPECT_NEAR(moments.std, 5e-4, 1.5e-5);
  // No random part: the systematic error alone, exactly.
  noise.sigma_rad = 0;
  TurntableModel exact(noise, 9);
  const TurntableMove move = exact.MoveTo(1.0);
  EXPECT_DOUBLE_EQ(move.true_rad, move.commanded_rad * 1.001 + 2e-3);
  // Determinism.
  TurntableModel a(noise, 4), b(noise, 4);
  EXPECT_EQ(a.MoveTo(0.5).true_rad, b.MoveTo(0.5).true_rad);
  noise.step_rad = 0;
  EXPECT_THROW(TurntableModel(noise, 1), std::invalid_argument);
  EXPECT_THROW(a.MoveTo(std::nan("")), std::invalid_argument);
}

std::vector<double> Levels(const cv::Mat& image) {
  std::vector<double> levels;
  for (int row = 0; row < image.rows; ++row) {
    const uint8_t* values = image.ptr<uint8_t>(row);
    levels.insert(levels.end(), values, values + image.cols * image.channels());
  }
  return levels;
}

TEST(ApplyImageNoise, FlatImageGetsTheModelledScatter) {
  ImageNoise noise;
  noise.read_sigma = 2.0;
  noise.shot_variance_per_level = 0.05;
  noise.gain_log_sigma = 0;  // gain exactly 1
  cv::Mat image(300, 400, CV_8UC3, cv::Scalar(128, 128, 128));
  ApplyImageNoise(image, noise, 11);
  const Moments moments = Measure(Levels(image));
  // Variance: read 4 + shot 0.05 * 128 + rounding 1/12.
  EXPECT_NEAR(moments.mean, 128.0, 0.05);
  EXPECT_NEAR(moments.std, std::sqrt(4 + 6.4 + 1.0 / 12), 0.03);
  // Brighter pixels scatter more (the shot term).
  cv::Mat bright(300, 400, CV_8UC1, cv::Scalar(220));
  ApplyImageNoise(bright, noise, 12);
  EXPECT_NEAR(Measure(Levels(bright)).std, std::sqrt(4 + 11.0 + 1.0 / 12), 0.05);
}

TEST(ApplyImageNoise, ExposureGainScalesTheImage) {
  ImageNoise noise;
  noise.read_sigma = 0;
  noise.shot_variance_per_level = 0;
  noise.gain_log_sigma = 0.1;
  std::vector<double> log_gains;
  for (uint64_t seed = 0; seed < 4000; ++seed)
    log_gains.push_back(std::log(ExposureGain(noise, seed)));
  const Moments moments = Measure(log_gains);
  EXPECT_NEAR(moments.mean, 0.0, 0.006);
  EXPECT_NEAR(moments.std, 0.1, 0.004);
  // Without pixel noise every pixel is its level times the seed's gain, rounded.
  cv::Mat image(20, 30, CV_8UC3, cv::Scalar(40, 100, 160));
  ApplyImageNoise(image, noise, 77);
  const double gain = ExposureGain(noise, 77);
  const cv::Vec3b pixel = image.at<cv::Vec3b>(5, 7);
  EXPECT_EQ(pixel[0], static_cast<uint8_t>(std::round(40 * gain)));
  EXPECT_EQ(pixel[1], static_cast<uint8_t>(std::round(100 * gain)));
  EXPECT_EQ(pixel[2], static_cast<uint8_t>(std::round(160 * gain)));
}

TEST(ApplyImageNoise, SaturatesAndIsDeterministic) {
  const ImageNoise noise;
  cv::Mat white(50, 60, CV_8UC3, cv::Scalar::all(255)), black(50, 60, CV_8UC3, cv::Scalar::all(0));
  ApplyImageNoise(white, noise, 1);
  ApplyImageNoise(black, noise, 1);
  double white_min = 255, black_max = 0;
  cv::minMaxLoc(white.reshape(1), &white_min);
  cv::minMaxLoc(black.reshape(1), nullptr, &black_max);
  EXPECT_LT(white_min, 255);  // noise reached some pixels...
  EXPECT_GT(black_max, 0);    // ...and stayed within 0..255 by saturation (uint8)
  cv::Mat a(40, 40, CV_8UC3, cv::Scalar(10, 120, 200)), b = a.clone(), c = a.clone();
  ApplyImageNoise(a, noise, 5);
  ApplyImageNoise(b, noise, 5);
  ApplyImageNoise(c, noise, 6);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_INF), 0.0);
}

TEST(ApplyImageNoise, RejectsBadInput) {
  cv::Mat empty;
  EXPECT_THROW(ApplyImageNoise(empty, {}, 1), std::invalid_argument);
  cv::Mat floats(10, 10, CV_32FC3, cv::Scalar::all(0.5));
  EXPECT_THROW(ApplyImageNoise(floats, {}, 1), std::invalid_argument);
  cv::Mat image(10, 10, CV_8UC3, cv::Scalar::all(100));
  ImageNoise bad;
  bad.read_sigma = -1;
  EXPECT_THROW(ApplyImageNoise(image, bad, 1), std::invalid_argument);
}

}  // namespace
}  // namespace avc::sim
