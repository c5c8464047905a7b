#include "sim/scene/plant.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "sim/scene/organ_mesh.h"
#include "sim/scene/plant_materials.h"
#include "sim/scene/plant_plan.h"
#include "sim/scene/pot.h"

namespace avc::sim {
namespace {

constexpr std::array<std::pair<PlantPreset, std::string_view>, 4> kPresetNames = {{
    {PlantPreset::kRosette, "rosette"},
    {PlantPreset::kBroadleaf, "broadleaf"},
    {PlantPreset::kStrap, "strap"},
    {PlantPreset::kBushy, "bushy"},
}};

// Stems are planned from 1 cm below the soil so they look rooted; without a pot the plant is
// lifted by that much to stand on the turntable.
constexpr float kRootDepth = 0.01f;

PlantPlan MakePlan(PlantPreset preset, PlantRandom& random) {
  switch (preset) {
    case PlantPreset::kRosette:
      return PlanRosette(random);
    case PlantPreset::kBroadleaf:
      return PlanBroadleaf(random);
    case PlantPreset::kStrap:
      return PlanStrap(random);
    case PlantPreset::kBushy:
      return PlanBushy(random);
  }
  throw std::invalid_argument(fmt::format("unknown plant preset {}", static_cast<int>(preset)));
}

size_t CountTriangles(const PlantPlan& plan, const MeshResolution& resolution, bool with_pot) {
  size_t count = with_pot ? PotTriangles(resolution) : 0;
  for (const TubeSpec& tube : plan.tubes) count += TubeTriangles(tube, resolution);
  return count + plan.leaves.size() * LeafTriangles(resolution);
}

MeshResolution ChooseResolution(const PlantPlan& plan, const PlantOptions& options) {
  if (options.leaf_segments > 0)
    return ResolutionFor(options.leaf_segments, plan.leaf_across_ratio);
  const size_t target = static_cast<size_t>(options.target_triangles);
  auto error = [&](const MeshResolution& resolution) {
    const size_t count = CountTriangles(plan, resolution, options.with_pot);
    return count > target ? count - target : target - count;
  };
  // Coarse: everything follows the leaf segments (the count grows with them)...
  MeshResolution best = ResolutionFor(4, plan.leaf_across_ratio);
  for (int segments = 5; segments <= 400; ++segments) {
    const MeshResolution candidate = ResolutionFor(segments, plan.leaf_across_ratio);
    if (error(candidate) < error(best)) best = candidate;
    if (CountTriangles(plan, candidate, options.with_pot) > target) break;
  }
  // ...fine: only the segments along the leaves, in steps of one row per leaf.
  const MeshResolution coarse = best;
  for (int along = coarse.leaf_along / 2; along <= 2 * coarse.leaf_along; ++along) {
    MeshResolution candidate = coarse;
    candidate.leaf_along = std::max(2, along);
    if (error(candidate) < error(best)) best = candidate;
  }
  return best;
}

}  // namespace

Scene GeneratePlant(PlantPreset preset, uint32_t seed, const PlantOptions& options) {
  if (options.leaf_segments < 0) {
    throw std::invalid_argument(
        fmt::format("PlantOptions.leaf_segments is {}, expected >= 0", options.leaf_segments));
  }
  if (options.leaf_segments == 0 && options.target_triangles <= 0) {
    throw std::invalid_argument(
        fmt::format("PlantOptions.target_triangles is {}, expected > 0", options.target_triangles));
  }
  PlantRandom shape_random(seed);
  const PlantPlan plan = MakePlan(preset, shape_random);
  const MeshResolution resolution = ChooseResolution(plan, options);

  Scene scene;
  scene.name = fmt::format("{} seed {}", PresetName(preset), seed);
  // Colours draw from their own stream, so they never change the shape.
  PlantRandom colour_random(seed ^ 0x9e3779b9u);
  scene.materials.push_back(PotMaterial(seed));
  scene.materials.push_back(SoilMaterial(seed));
  scene.materials.push_back(StemMaterial("stem", plan.stem_rgb, colour_random.Bits()));
  scene.materials.push_back(
      StemMaterial("petiole", (plan.stem_rgb * 1.15f).cwiseMin(1.0f), colour_random.Bits()));
  for (size_t i = 0; i < plan.leaves.size(); ++i) {
    scene.materials.push_back(
        LeafMaterial(plan, plan.leaves[i], static_cast<int>(i), colour_random));
  }

  geometry::Mesh& mesh = scene.mesh;
  const size_t triangles = CountTriangles(plan, resolution, options.with_pot);
  mesh.faces.reserve(triangles);
  mesh.face_labels.reserve(triangles);
  mesh.face_materials.reserve(triangles);
  if (options.with_pot) {
    AppendPotAndSoil(resolution, seed, kPotMaterial, kSoilMaterial, &mesh);
  }
  const Eigen::Vector3f base(0.0f, 0.0f, options.with_pot ? SoilHeight() : kRootDepth);
  for (const TubeSpec& tube : plan.tubes) {
    const int32_t material =
        tube.label == geometry::labels::kPetiole ? kPetioleMaterial : kStemMaterial;
    AppendTube(tube, base, resolution, material, &mesh);
  }
  for (size_t i = 0; i < plan.leaves.size(); ++i) {
    const int32_t index = static_cast<int32_t>(i);
    AppendLeaf(plan.leaves[i], base, resolution, geometry::labels::kLeafBase + index,
               kFirstLeafMaterial + index, &mesh);
  }
  return scene;
}

std::string_view PresetName(PlantPreset preset) {
  for (const auto& [value, name] : kPresetNames) {
    if (value == preset) return name;
  }
  throw std::invalid_argument(fmt::format("unknown plant preset {}", static_cast<int>(preset)));
}

PlantPreset ParsePreset(std::string_view name) {
  std::string valid;
  for (const auto& [value, preset_name] : kPresetNames) {
    if (preset_name == name) return value;
    valid += valid.empty() ? "" : ", ";
    valid += preset_name;
  }
  throw std::invalid_argument(
      fmt::format("unknown plant preset '{}' (valid presets: {})", name, valid));
}

std::vector<PlantPreset> AllPresets() {
  std::vector<PlantPreset> presets;
  for (const auto& [value, name] : kPresetNames) presets.push_back(value);
  return presets;
}

}  // namespace avc::sim
