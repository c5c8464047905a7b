#include "sim/render/background.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace avc::sim {
namespace {

constexpr int kNodeSpacingPx = 8;
constexpr int kOctaves = 3;

uint32_t Hash(int32_t x, int32_t y, int32_t z, uint32_t seed) {
  uint32_t h = seed * 0x9E3779B9u;
  h ^= static_cast<uint32_t>(x) * 0x85EBCA6Bu;
  h = (h << 13) | (h >> 19);
  h ^= static_cast<uint32_t>(y) * 0xC2B2AE35u;
  h = (h << 13) | (h >> 19);
  h ^= static_cast<uint32_t>(z) * 0x27D4EB2Fu;
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  h *= 0x297A2D39u;
  h ^= h >> 15;
  return h;
}

double Lattice(int32_t x, int32_t y, int32_t z, uint32_t seed) {
  return static_cast<double>(Hash(x, y, z, seed) >> 8) / 16777216.0;
}

double Smooth(double t) { return t * t * (3 - 2 * t); }

// Trilinear value noise in [0, 1).
double ValueNoise(const Eigen::Vector3d& p, uint32_t seed) {
  const Eigen::Vector3d cell = p.array().floor();
  const int32_t x = static_cast<int32_t>(cell.x()), y = static_cast<int32_t>(cell.y()),
                z = static_cast<int32_t>(cell.z());
  const double tx = Smooth(p.x() - cell.x()), ty = Smooth(p.y() - cell.y()),
               tz = Smooth(p.z() - cell.z());
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  const double x00 = lerp(Lattice(x, y, z, seed), Lattice(x + 1, y, z, seed), tx);
  const double x10 = lerp(Lattice(x, y + 1, z, seed), Lattice(x + 1, y + 1, z, seed), tx);
  const double x01 = lerp(Lattice(x, y, z + 1, seed), Lattice(x + 1, y, z + 1, seed), tx);
  const double x11 = lerp(Lattice(x, y + 1, z + 1, seed), Lattice(x + 1, y + 1, z + 1, seed), tx);
  return lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz);
}

}  // namespace

float ClothFactor(const Background& background, const Eigen::Vector3d& direction_world) {
  const double frequency = 1.0 / (background.feature_deg * M_PI / 180.0);
  double sum = 0, amplitude = 1, total = 0;
  Eigen::Vector3d p = direction_world * frequency;
  for (int octave = 0; octave < kOctaves; ++octave) {
    sum += amplitude * ValueNoise(p, background.seed + 7919u * static_cast<uint32_t>(octave));
    total += amplitude;
    amplitude *= 0.5;
    p *= 2.0;
  }
  return static_cast<float>(1.0 + background.contrast * (2.0 * sum / total - 1.0));
}

BackgroundImage::BackgroundImage(const Background& background, const LensModel& lens,
                                 const Eigen::Matrix3d& R_world_cam)
    : rgb_(background.rgb), plain_(background.kind == Background::Kind::kPlain) {
  if (plain_) return;
  const int width = lens.intrinsics().width, height = lens.intrinsics().height;
  nodes_x_ = (width - 1) / kNodeSpacingPx + 2;
  nodes_y_ = (height - 1) / kNodeSpacingPx + 2;
  factor_.resize(static_cast<size_t>(nodes_x_) * nodes_y_);
  tbb::parallel_for(0, nodes_y_, [&](int j) {
    for (int i = 0; i < nodes_x_; ++i) {
      const Eigen::Vector2d n = lens.NormalisedOf(
          {static_cast<double>(i * kNodeSpacingPx), static_cast<double>(j * kNodeSpacingPx)});
      const Eigen::Vector3d direction = R_world_cam * Eigen::Vector3d(n.x(), n.y(), 1).normalized();
      factor_[static_cast<size_t>(j) * nodes_x_ + i] = ClothFactor(background, direction);
    }
  });
}

void BackgroundImage::Row(int v, int u0, int u1, Eigen::Vector3f* out) const {
  if (plain_) {
    std::fill(out, out + (u1 - u0), rgb_);
    return;
  }
  const int j = v / kNodeSpacingPx;
  const float ty = static_cast<float>(v - j * kNodeSpacingPx) / kNodeSpacingPx;
  const float* row0 = factor_.data() + static_cast<size_t>(j) * nodes_x_;
  const float* row1 = row0 + nodes_x_;
  for (int u = u0; u < u1; ++u) {
    const int i = u / kNodeSpacingPx;
    const float tx = static_cast<float>(u - i * kNodeSpacingPx) / kNodeSpacingPx;
    const float left = row0[i] + (row1[i] - row0[i]) * ty;
    const float right = row0[i + 1] + (row1[i + 1] - row0[i + 1]) * ty;
    out[u - u0] = rgb_ * (left + (right - left) * tx);
  }
}

}  // namespace avc::sim
