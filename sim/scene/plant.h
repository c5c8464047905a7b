#pragma once

// Procedural potted plants for the simulated cell: seeded and deterministic (same preset, seed
// and options → bit-identical mesh). Four presets of contrasting morphology, like the species of
// the paper. The pot (15 cm across) stands on the turntable top at z = 0, the plant axis is the
// z axis, z up, metres.
//
// Resolution: the default plant has about 40k triangles. Set options.target_triangles (e.g.
// 100000 for benchmarks) to get close to another count, or options.leaf_segments to fix the
// number of segments along each leaf directly (tubes, pot and soil follow it).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sim/scene/scene.h"

namespace avc::sim {

enum class PlantPreset {
  kRosette,    // long arching leaves from a central base (bromeliad, aloe)
  kBroadleaf,  // broad round leaves on petioles around a short stem (pumpkin, brassica)
  kStrap,      // strap leaves alternating along an upright stem (cordyline, maize)
  kBushy,      // many small leaves on branching stems (chilli)
};

struct PlantOptions {
  int leaf_segments = 0;         // segments along each leaf; 0 = chosen from target_triangles
  int target_triangles = 40000;  // approximate total (within a few percent) when leaf_segments is 0
  bool with_pot = true;          // pot and soil; without them the plant base is at z = 0
};

// Materials of a generated scene, by index: these four, then one per leaf (kFirstLeafMaterial + i
// for leaf i, label kLeafBase + i).
inline constexpr int32_t kPotMaterial = 0;
inline constexpr int32_t kSoilMaterial = 1;
inline constexpr int32_t kStemMaterial = 2;
inline constexpr int32_t kPetioleMaterial = 3;
inline constexpr int32_t kFirstLeafMaterial = 4;

// Throws std::invalid_argument for leaf_segments < 0, target_triangles <= 0 (when used).
Scene GeneratePlant(PlantPreset preset, uint32_t seed, const PlantOptions& options = {});

// "rosette", "broadleaf", "strap", "bushy".
std::string_view PresetName(PlantPreset preset);
// Inverse of PresetName; throws std::invalid_argument listing the valid names.
PlantPreset ParsePreset(std::string_view name);
std::vector<PlantPreset> AllPresets();

}  // namespace avc::sim
