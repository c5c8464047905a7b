// Rosette preset (bromeliad, aloe): long lanceolate leaves arching out from a central base in a
// golden-angle spiral; outer leaves are older, longer and droop more than the upright inner ones.

#include <cmath>

#include "sim/scene/plant_plan.h"

namespace avc::sim {

PlantPlan PlanRosette(PlantRandom& random) {
  PlantPlan plan;
  plan.leaf_rgb = {0.06f, 0.15f, 0.07f};  // grey-blue green
  plan.stem_rgb = {0.09f, 0.14f, 0.05f};
  plan.venation = Venation::kParallel;  // monocots
  plan.leaf_across_ratio = 0.4f;

  // A short stout core where the leaf bases meet, rooted in the soil.
  TubeSpec core;
  core.points = {{0, 0, -0.01f}, {0, 0, 0.02f}, {0, 0, 0.035f}};
  core.radii = {0.014f, 0.012f, 0.006f};
  core.label = geometry::labels::kStem;
  plan.tubes.push_back(core);

  const int count = random.Int(16, 22);
  const float start = random.Uniform(0.0f, 2.0f * kPi);
  for (int i = 0; i < count; ++i) {
    const float age = static_cast<float>(i) / static_cast<float>(count - 1);
    LeafSpec leaf;
    leaf.age = age;
    leaf.azimuth = start + static_cast<float>(i) * kGoldenAngle + random.Uniform(-0.12f, 0.12f);
    const float radius = 0.004f + 0.010f * (1.0f - age);
    leaf.base = {radius * std::cos(leaf.azimuth), radius * std::sin(leaf.azimuth),
                 0.003f + 0.022f * age};
    leaf.length = (0.30f - 0.13f * age) * random.Uniform(0.88f, 1.12f);
    leaf.half_width = leaf.length * random.Uniform(0.085f, 0.11f);
    leaf.elevation = Degrees(32.0f + 48.0f * age + random.Uniform(-6.0f, 6.0f));
    leaf.droop = Degrees((75.0f - 55.0f * age) * random.Uniform(0.8f, 1.2f));
    leaf.droop_power = 1.6f;
    leaf.side_bend = random.Uniform(-0.25f, 0.25f);
    leaf.outline = LeafOutline::kLanceolate;
    leaf.fold = random.Uniform(0.25f, 0.45f);
    leaf.fold_power = 2.0f;  // U-shaped channel
    leaf.twist = random.Uniform(-0.5f, 0.5f);
    leaf.wave_amplitude = random.Uniform(0.0f, 0.04f);
    leaf.wave_count = random.Uniform(2.0f, 4.0f);
    leaf.wave_phase = random.Uniform(0.0f, 1.0f);
    plan.leaves.push_back(leaf);
  }
  return plan;
}

}  // namespace avc::sim
