#include "sim/scene/material.h"

#include <algorithm>
#include <cmath>

#include "sim/scene/procedural_noise.h"

namespace avc::sim {
namespace {

using noise::CellValue;
using noise::LineProfile;
using noise::ValueNoise;

// Distance (in the units of period) from x to the nearest multiple of period.
float DistanceToGrid(float x, float period) {
  const float q = x / period;
  const float f = q - static_cast<float>(noise::FloorToInt(q));
  return std::min(f, 1.0f - f) * period;
}

Eigen::Vector3f Mix(const Eigen::Vector3f& a, const Eigen::Vector3f& b, float t) {
  return a + (b - a) * t;
}

// Low-frequency colour variation in about -0.5..0.5 over cells of `cell` metres.
float LowFrequency(float x, float y, float cell, uint32_t seed) {
  return 0.65f * ValueNoise(x / cell, y / cell, seed) +
         0.35f * ValueNoise(x / (0.4f * cell), y / (0.4f * cell), seed + 1) - 0.5f;
}

// Fine multiplicative speckle around 1 (amplitude is the total swing).
float Speckle(float x, float y, float cell, float amplitude, uint32_t seed) {
  const float n = 0.6f * ValueNoise(x / cell, y / cell, seed) +
                  0.4f * ValueNoise(x / (0.45f * cell), y / (0.45f * cell), seed + 1);
  return 1.0f + amplitude * (n - 0.5f);
}

// Leaf veins (0..1): midrib plus lateral or parallel veins, from leaf coordinates.
float Veins(const Material& m, float u, float v, float scale) {
  const float length = m.uv_extent.x();
  const float half_width = m.uv_extent.y();
  const float across = std::abs(v) * half_width;  // metres from the midrib
  const float midrib = LineProfile(across, 0.0015f * (1.0f - 0.7f * std::clamp(u, 0.0f, 1.0f)));
  float lateral = 0.0f;
  if (m.venation == Venation::kPinnate) {
    // Veins leave the midrib towards the tip and fade towards the margin.
    const float spacing = std::clamp(length / 14.0f, 0.004f, 0.02f) / scale;
    const float along = u * length - 0.8f * across;
    lateral = LineProfile(DistanceToGrid(along, spacing), 0.0006f) *
              (1.0f - 0.6f * std::min(std::abs(v), 1.0f));
  } else if (m.venation == Venation::kParallel) {
    lateral = 0.6f * LineProfile(DistanceToGrid(across, 0.0025f / scale), 0.0004f);
  } else {
    return 0.0f;
  }
  return std::max(midrib, 0.7f * lateral);
}

Eigen::Vector3f LeafAlbedo(const Material& m, float x, float y, float u, float v) {
  const float s = m.detail_scale;
  const float low = LowFrequency(x, y, 0.03f / s, m.seed);
  Eigen::Vector3f color = m.base_rgb * (1.0f + 2.0f * m.variation * low);
  // Slight hue drift: green varies on its own so leaves are not uniformly tinted.
  color.y() *=
      1.0f + m.variation * (ValueNoise(x / (0.02f / s), y / (0.02f / s), m.seed + 7) - 0.5f);
  color = Mix(color, m.detail_rgb, 0.75f * Veins(m, u, v, s));
  return color * Speckle(x, y, 0.0012f / s, 0.36f, m.seed + 2);
}

Eigen::Vector3f StemAlbedo(const Material& m, float x, float y) {
  // uv = (around, along) in metres: streaks run along the stem.
  const float s = m.detail_scale;
  const float streak = ValueNoise(x / (0.0008f / s), y / (0.012f / s), m.seed + 3);
  Eigen::Vector3f color =
      m.base_rgb * (1.0f + 2.0f * m.variation * LowFrequency(x, y, 0.04f / s, m.seed));
  color = Mix(color, m.detail_rgb, 0.5f * streak);
  return color * Speckle(x, y, 0.001f / s, 0.25f, m.seed + 2);
}

Eigen::Vector3f PotAlbedo(const Material& m, float x, float y) {
  const float s = m.detail_scale;
  const Eigen::Vector3f color =
      m.base_rgb * (1.0f + 2.0f * m.variation * LowFrequency(x, y, 0.025f / s, m.seed));
  return Mix(color, m.detail_rgb,
             0.25f * ValueNoise(x / (0.004f / s), y / (0.004f / s), m.seed + 5)) *
         Speckle(x, y, 0.001f / s, 0.15f, m.seed + 2);
}

Eigen::Vector3f SoilAlbedo(const Material& m, float x, float y) {
  // Grains of about 1.5 mm: blocky per-grain shade, darker clumps, rare light particles.
  const float s = m.detail_scale;
  const float grain = 0.0015f / s;
  // Grains on a rotated grid, blended with smooth noise, so they do not line up with the uvs.
  const float gx = (0.866f * x - 0.5f * y) / grain;
  const float gy = (0.5f * x + 0.866f * y) / grain;
  const float shade =
      0.6f * CellValue(gx, gy, m.seed + 4) + 0.4f * ValueNoise(1.7f * gx, 1.7f * gy, m.seed + 8);
  const float clump = ValueNoise(x / (0.006f / s), y / (0.006f / s), m.seed + 5);
  Eigen::Vector3f color =
      m.base_rgb * (1.0f + 2.0f * m.variation * LowFrequency(x, y, 0.03f / s, m.seed));
  color = Mix(color, m.detail_rgb, std::clamp(1.6f * clump - 0.5f, 0.0f, 1.0f));
  color *= 0.55f + 0.9f * shade;
  if (CellValue(gx, gy, m.seed + 6) > 0.992f) {
    color = Eigen::Vector3f(0.3f, 0.29f, 0.27f);  // perlite / sand grain
  }
  return color;
}

Eigen::Vector3f PlainAlbedo(const Material& m, float x, float y) {
  // All of a plain material's texture scales with variation: 0 gives exactly base_rgb.
  const float s = m.detail_scale;
  const Eigen::Vector3f color =
      m.base_rgb * (1.0f + 2.0f * m.variation * LowFrequency(x, y, 0.03f / s, m.seed));
  return color * Speckle(x, y, 0.0015f / s, 2.0f * m.variation, m.seed + 2);
}

}  // namespace

Eigen::Vector3f Albedo(const Material& material, const Eigen::Vector2f& uv) {
  if (!uv.allFinite()) return Eigen::Vector3f::Zero();
  const float x = uv.x() * material.uv_extent.x();
  const float y = uv.y() * material.uv_extent.y();
  Eigen::Vector3f color = material.base_rgb;
  switch (material.kind) {
    case MaterialKind::kLeaf:
      color = LeafAlbedo(material, x, y, uv.x(), uv.y());
      break;
    case MaterialKind::kStem:
      color = StemAlbedo(material, x, y);
      break;
    case MaterialKind::kPot:
      color = PotAlbedo(material, x, y);
      break;
    case MaterialKind::kSoil:
      color = SoilAlbedo(material, x, y);
      break;
    case MaterialKind::kPlain:
      color = PlainAlbedo(material, x, y);
      break;
  }
  // NaN-safe clamp (a NaN uv gives black, not NaN).
  for (int k = 0; k < 3; ++k) color[k] = color[k] > 0.0f ? std::min(color[k], 1.0f) : 0.0f;
  return color;
}

}  // namespace avc::sim
