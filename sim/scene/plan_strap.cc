// Strap preset (cordyline, maize): long strap leaves alternating on opposite sides of an upright
// stem (slowly drifting, so the plant is not flat), arching over; a rolled young whorl on top.

#include <cmath>

#include "sim/scene/plant_plan.h"

namespace avc::sim {

PlantPlan PlanStrap(PlantRandom& random) {
  PlantPlan plan;
  plan.leaf_rgb = {0.05f, 0.16f, 0.03f};
  plan.stem_rgb = {0.09f, 0.16f, 0.045f};
  plan.venation = Venation::kParallel;
  plan.leaf_across_ratio = 0.3f;

  const float height = random.Uniform(0.18f, 0.26f);
  const float lean_azimuth = random.Uniform(0.0f, 2.0f * kPi);
  const float lean = Degrees(random.Uniform(0.0f, 6.0f));
  auto stem_point = [&](float t) {
    const float sideways = std::sin(lean) * height * std::pow(t, 1.5f);
    return Eigen::Vector3f(sideways * std::cos(lean_azimuth), sideways * std::sin(lean_azimuth),
                           -0.01f + (height + 0.01f) * t);
  };
  TubeSpec stem;
  stem.label = geometry::labels::kStem;
  for (int k = 0; k <= 12; ++k) {
    const float t = static_cast<float>(k) / 12.0f;
    stem.points.push_back(stem_point(t));
    stem.radii.push_back(0.009f - 0.004f * t);
  }
  plan.tubes.push_back(stem);

  const int count = random.Int(9, 12);
  const float phase = random.Uniform(0.0f, 2.0f * kPi);
  const float drift = random.Uniform(0.12f, 0.3f);
  for (int i = 0; i < count; ++i) {
    const float age = static_cast<float>(i) / static_cast<float>(count - 1);
    LeafSpec leaf;
    leaf.age = age;
    leaf.azimuth = phase + static_cast<float>(i) * (kPi + drift) + random.Uniform(-0.2f, 0.2f);
    const float t = 0.06f + 0.9f * std::pow(age, 0.9f);
    leaf.base = stem_point(t) + (0.007f - 0.003f * t) * Heading(leaf.azimuth, 0.0f);
    leaf.length = 0.36f * (1.0f - 0.5f * age) * random.Uniform(0.85f, 1.15f);
    leaf.half_width = random.Uniform(0.017f, 0.025f) * (1.0f - 0.3f * age);
    leaf.elevation = Degrees(50.0f + 30.0f * age + random.Uniform(-6.0f, 6.0f));
    leaf.droop = Degrees((110.0f - 70.0f * age) * random.Uniform(0.8f, 1.15f));
    leaf.droop_power = 1.4f;
    leaf.side_bend = random.Uniform(-0.3f, 0.3f);
    leaf.outline = LeafOutline::kStrap;
    leaf.fold = random.Uniform(0.15f, 0.35f);
    leaf.fold_power = 1.0f;  // V-shaped about the midrib
    leaf.twist = random.Uniform(-0.8f, 0.8f);
    leaf.wave_amplitude = random.Uniform(0.02f, 0.06f);
    leaf.wave_count = random.Uniform(5.0f, 9.0f);
    leaf.wave_phase = random.Uniform(0.0f, 1.0f);
    plan.leaves.push_back(leaf);
  }
  // The whorl: young leaves still rolled, pointing up out of the stem top.
  const int whorl = random.Int(1, 2);
  for (int i = 0; i < whorl; ++i) {
    LeafSpec leaf;
    leaf.age = 1.0f;
    leaf.azimuth = phase + static_cast<float>(count + i) * (kPi + drift);
    leaf.base = stem_point(1.0f);
    leaf.length = random.Uniform(0.12f, 0.18f);
    leaf.half_width = 0.012f;
    leaf.elevation = Degrees(random.Uniform(80.0f, 88.0f));
    leaf.droop = Degrees(random.Uniform(10.0f, 25.0f));
    leaf.outline = LeafOutline::kStrap;
    leaf.fold = 0.9f;
    leaf.fold_power = 1.5f;
    leaf.twist = random.Uniform(-0.4f, 0.4f);
    plan.leaves.push_back(leaf);
  }
  return plan;
}

}  // namespace avc::sim
