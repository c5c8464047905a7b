#include "sim/scene/plant_materials.h"

#include <fmt/format.h>

#include <utility>

namespace avc::sim {

Material PotMaterial(uint32_t seed) {
  Material m;
  m.kind = MaterialKind::kPot;
  if ((seed >> 3) % 2 == 0) {
    m.name = "pot (terracotta)";
    m.base_rgb = {0.42f, 0.13f, 0.055f};
    m.detail_rgb = {0.30f, 0.09f, 0.04f};
  } else {
    m.name = "pot (dark grey plastic)";
    m.base_rgb = {0.035f, 0.036f, 0.04f};
    m.detail_rgb = {0.06f, 0.06f, 0.066f};
  }
  m.variation = 0.06f;
  m.seed = seed * 2654435761u + 11u;
  return m;
}

Material SoilMaterial(uint32_t seed) {
  Material m;
  m.name = "soil";
  m.kind = MaterialKind::kSoil;
  m.base_rgb = {0.085f, 0.052f, 0.03f};
  m.detail_rgb = {0.03f, 0.02f, 0.012f};
  m.variation = 0.15f;
  m.seed = seed * 2654435761u + 23u;
  return m;
}

Material StemMaterial(std::string name, const Eigen::Vector3f& rgb, uint32_t seed) {
  Material m;
  m.name = std::move(name);
  m.kind = MaterialKind::kStem;
  m.base_rgb = rgb;
  m.detail_rgb = rgb.cwiseProduct(Eigen::Vector3f(1.5f, 1.35f, 1.2f));
  m.variation = 0.1f;
  m.seed = seed;
  return m;
}

Material LeafMaterial(const PlantPlan& plan, const LeafSpec& leaf, int index, PlantRandom& random) {
  Material m;
  m.name = fmt::format("leaf {}", index);
  m.kind = MaterialKind::kLeaf;
  const float brightness = random.Uniform(0.82f, 1.18f) * (1.0f + 0.3f * leaf.age);
  const float yellowness = random.Uniform(-0.12f, 0.25f) + 0.3f * leaf.age;
  m.base_rgb = plan.leaf_rgb * brightness;
  m.base_rgb.x() *= 1.0f + yellowness;
  m.base_rgb.z() *= 1.0f - 0.5f * yellowness;
  m.base_rgb = m.base_rgb.cwiseMin(1.0f);
  // Veins: lighter and yellower than the blade.
  m.detail_rgb = (m.base_rgb.cwiseProduct(Eigen::Vector3f(1.9f, 1.5f, 1.3f)) +
                  Eigen::Vector3f(0.02f, 0.03f, 0.0f))
                     .cwiseMin(1.0f);
  m.variation = 0.12f;
  m.detail_scale = 1.0f;
  m.venation = plan.venation;
  m.uv_extent = {leaf.length, leaf.half_width};
  m.seed = random.Bits();
  return m;
}

}  // namespace avc::sim
