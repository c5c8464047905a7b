// Procedural albedo: deterministic, in range, textured enough for stereo, and plausibly coloured.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim/scene/material.h"
#include "sim/scene/plant.h"

namespace avc::sim {
namespace {

struct Stats {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double luminance_std = 0;  // relative to the mean luminance
};

double Luminance(const Eigen::Vector3f& c) {
  return 0.2126 * c.x() + 0.7152 * c.y() + 0.0722 * c.z();
}

// Albedo statistics on an n x n grid over u in [u0, u1], v in [v0, v1].
Stats GridStats(const Material& m, float u0, float u1, float v0, float v1, int n = 96) {
  Stats stats;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2f uv(u0 + (u1 - u0) * (i + 0.5f) / n, v0 + (v1 - v0) * (j + 0.5f) / n);
      const Eigen::Vector3f c = Albedo(m, uv);
      stats.mean += c.cast<double>();
      const double l = Luminance(c);
      sum += l;
      sum2 += l * l;
    }
  }
  const double count = static_cast<double>(n) * n;
  stats.mean /= count;
  const double mean = sum / count;
  stats.luminance_std = std::sqrt(std::max(0.0, sum2 / count - mean * mean)) / mean;
  return stats;
}

std::vector<Material> GeneratedMaterials() {
  std::vector<Material> all;
  for (PlantPreset preset : AllPresets()) {
    const Scene scene = GeneratePlant(preset, 21, PlantOptions{.leaf_segments = 4});
    all.insert(all.end(), scene.materials.begin(), scene.materials.end());
  }
  return all;
}

TEST(SceneMaterial, AlbedoIsDeterministicAndInRange) {
  for (const Material& m : GeneratedMaterials()) {
    for (int i = 0; i < 400; ++i) {
      const Eigen::Vector2f uv(std::fmod(i * 0.6180339f, 1.0f), std::fmod(i * 0.41421f, 2.0f) - 1);
      const Eigen::Vector3f a = Albedo(m, uv);
      EXPECT_EQ(a, Albedo(m, uv)) << m.name;
      EXPECT_TRUE((a.array() >= 0.0f).all() && (a.array() <= 1.0f).all()) << m.name;
    }
  }
  Material leaf;
  leaf.kind = MaterialKind::kLeaf;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(Albedo(leaf, Eigen::Vector2f(nan, 0.5f)), Eigen::Vector3f::Zero());
}

TEST(SceneMaterial, LeavesAreGreenAndTexturedForStereo) {
  int leaves = 0;
  for (const Material& m : GeneratedMaterials()) {
    if (m.kind != MaterialKind::kLeaf) continue;
    ++leaves;
    const Stats whole = GridStats(m, 0.0f, 1.0f, -1.0f, 1.0f);
    EXPECT_GT(whole.mean.y(), whole.mean.x()) << m.name;
    EXPECT_GT(whole.mean.y(), whole.mean.z()) << m.name;
    EXPECT_GT(whole.luminance_std, 0.08) << m.name;
    // Fine texture: even a 1 cm patch (where stereo matches) varies.
    const float patch_u = 0.01f / m.uv_extent.x();
    const float patch_v = 0.01f / m.uv_extent.y();
    EXPECT_GT(GridStats(m, 0.5f, 0.5f + patch_u, 0.3f, 0.3f + patch_v, 32).luminance_std, 0.05)
        << m.name;
  }
  EXPECT_GT(leaves, 50);
}

TEST(SceneMaterial, MidribIsLighterThanTheBlade) {
  Material m;
  m.kind = MaterialKind::kLeaf;
  m.base_rgb = {0.05f, 0.15f, 0.03f};
  m.detail_rgb = {0.12f, 0.25f, 0.05f};
  m.uv_extent = {0.2f, 0.03f};
  m.seed = 5;
  const Stats midrib = GridStats(m, 0.1f, 0.6f, -0.005f, 0.005f, 64);
  const Stats blade = GridStats(m, 0.1f, 0.6f, 0.3f, 0.35f, 64);
  EXPECT_GT(Luminance(midrib.mean.cast<float>()), 1.3 * Luminance(blade.mean.cast<float>()));
  // Pinnate leaves have lateral veins: along a line beside the midrib, brightness oscillates
  // with the vein spacing; without venation the line is much flatter.
  const Stats lateral = GridStats(m, 0.1f, 0.6f, 0.2f, 0.2f, 256);
  m.venation = Venation::kNone;
  const Stats plain = GridStats(m, 0.1f, 0.6f, 0.2f, 0.2f, 256);
  EXPECT_GT(lateral.luminance_std, 1.2 * plain.luminance_std);
}

TEST(SceneMaterial, PlainMaterialVariesOnlyByItsVariation) {
  Material m;
  m.kind = MaterialKind::kPlain;
  m.base_rgb = {0.3f, 0.2f, 0.1f};
  m.variation = 0.0f;
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(Albedo(m, Eigen::Vector2f(i * 0.0137f, i * -0.0291f)), m.base_rgb);
  }
  m.variation = 0.1f;
  EXPECT_GT(GridStats(m, 0.0f, 0.05f, 0.0f, 0.05f).luminance_std, 0.03);
}

TEST(SceneMaterial, SeedsChangeTheTexture) {
  Material a;
  a.kind = MaterialKind::kLeaf;
  a.base_rgb = {0.05f, 0.15f, 0.03f};
  a.uv_extent = {0.2f, 0.03f};
  Material b = a;
  b.seed = 1;
  int different = 0;
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector2f uv(i / 100.0f, 0.37f);
    different += Albedo(a, uv) != Albedo(b, uv);
  }
  EXPECT_GT(different, 90);
}

TEST(SceneMaterial, SoilIsBrownAndGranularThePotMild) {
  const Scene scene = GeneratePlant(PlantPreset::kRosette, 2, PlantOptions{.leaf_segments = 4});
  const Material& soil = scene.materials[kSoilMaterial];
  const Material& pot = scene.materials[kPotMaterial];
  // Soil and pot uvs are metres: a 5 cm square.
  const Stats soil_stats = GridStats(soil, 0.0f, 0.05f, 0.0f, 0.05f);
  const Stats pot_stats = GridStats(pot, 0.0f, 0.05f, 0.0f, 0.05f);
  EXPECT_GT(soil_stats.mean.x(), soil_stats.mean.y());
  EXPECT_GT(soil_stats.mean.y(), soil_stats.mean.z());
  EXPECT_GT(soil_stats.luminance_std, 0.2);
  EXPECT_GT(pot_stats.luminance_std, 0.02);
  EXPECT_LT(pot_stats.luminance_std, soil_stats.luminance_std);
  const Stats stem = GridStats(scene.materials[kStemMaterial], 0.0f, 0.02f, 0.0f, 0.05f);
  EXPECT_GT(stem.luminance_std, 0.03);
  EXPECT_GT(stem.mean.y(), stem.mean.x());
}

}  // namespace
}  // namespace avc::sim
