// Broadleaf preset (pumpkin, brassica): broad round leaves with wavy margins on long petioles
// that arch out from a short stem; older leaves sit lower and spread wider.

#include <cmath>

#include "sim/scene/plant_plan.h"

namespace avc::sim {

PlantPlan PlanBroadleaf(PlantRandom& random) {
  PlantPlan plan;
  plan.leaf_rgb = {0.035f, 0.12f, 0.025f};
  plan.stem_rgb = {0.08f, 0.15f, 0.04f};
  plan.venation = Venation::kPinnate;
  plan.leaf_across_ratio = 0.9f;

  const float height = random.Uniform(0.04f, 0.07f);
  const float lean_azimuth = random.Uniform(0.0f, 2.0f * kPi);
  const float lean = Degrees(random.Uniform(0.0f, 8.0f));
  auto stem_point = [&](float t) {
    const float sideways = std::sin(lean) * height * t * t;
    return Eigen::Vector3f(sideways * std::cos(lean_azimuth), sideways * std::sin(lean_azimuth),
                           -0.01f + (height + 0.01f) * t);
  };
  TubeSpec stem;
  stem.label = geometry::labels::kStem;
  for (int k = 0; k <= 8; ++k) {
    const float t = static_cast<float>(k) / 8.0f;
    stem.points.push_back(stem_point(t));
    stem.radii.push_back(0.009f - 0.003f * t);
  }
  plan.tubes.push_back(stem);

  const int count = random.Int(8, 11);
  const float start = random.Uniform(0.0f, 2.0f * kPi);
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> tangents;
  for (int i = 0; i < count; ++i) {
    const float age = static_cast<float>(i) / static_cast<float>(count - 1);
    const float azimuth =
        start + static_cast<float>(i) * kGoldenAngle + random.Uniform(-0.15f, 0.15f);
    const Eigen::Vector3f node = stem_point(0.2f + 0.8f * age) + 0.005f * Heading(azimuth, 0.0f);

    // Petiole: rises steeply and bends outwards.
    const float petiole_length = (0.14f - 0.07f * age) * random.Uniform(0.85f, 1.15f);
    const float petiole_elevation = Degrees(45.0f + 35.0f * age + random.Uniform(-5.0f, 5.0f));
    const float petiole_droop = Degrees((35.0f - 15.0f * age) * random.Uniform(0.7f, 1.3f));
    ArcCurve(node, azimuth, petiole_elevation, petiole_droop, 1.0f, 0.0f, petiole_length, 10,
             &points, &tangents);
    TubeSpec petiole;
    petiole.label = geometry::labels::kPetiole;
    petiole.points = points;
    for (size_t k = 0; k < points.size(); ++k) {
      const float t = static_cast<float>(k) / static_cast<float>(points.size() - 1);
      petiole.radii.push_back((0.0036f - 0.0012f * t) * (1.0f - 0.3f * age));
    }
    plan.tubes.push_back(petiole);

    // Blade: roughly horizontal, facing up, cupped or domed, ruffled margin.
    LeafSpec leaf;
    leaf.age = age;
    leaf.base = points.back();
    leaf.azimuth = azimuth;
    leaf.elevation = Degrees(random.Uniform(-5.0f, 20.0f) + 25.0f * age);
    leaf.droop = Degrees(random.Uniform(15.0f, 40.0f));
    leaf.droop_power = 1.2f;
    leaf.side_bend = random.Uniform(-0.2f, 0.2f);
    leaf.length = (0.18f - 0.07f * age) * random.Uniform(0.85f, 1.15f);
    leaf.half_width = leaf.length * random.Uniform(0.45f, 0.55f);
    leaf.outline = LeafOutline::kOvate;
    leaf.fold = random.Uniform(-0.1f, 0.25f);
    leaf.fold_power = 2.0f;
    leaf.twist = random.Uniform(-0.3f, 0.3f);
    leaf.wave_amplitude = random.Uniform(0.03f, 0.09f);
    leaf.wave_count = random.Uniform(3.0f, 6.0f);
    leaf.wave_phase = random.Uniform(0.0f, 1.0f);
    plan.leaves.push_back(leaf);
  }
  return plan;
}

}  // namespace avc::sim
