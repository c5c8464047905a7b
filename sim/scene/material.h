#pragma once

// Surface appearance of the simulated world: a procedural, seeded texture per material, so
// leaves carry the veins and colour variation stereo needs, and rendering stays deterministic.

#include <Eigen/Core>
#include <cstdint>
#include <string>

namespace avc::sim {

// kLeaf: blade colour, veins and speckle from leaf uvs; kStem: streaks along the stem; kPot: mild
// mottling; kSoil: granular; kPlain: base_rgb with noise of amplitude variation (0: exactly
// base_rgb).
enum class MaterialKind { kLeaf, kStem, kPot, kSoil, kPlain };

// How a leaf's veins run: lateral veins off the midrib (dicots), veins parallel to the midrib
// (grasses, cordyline), or none (meshes whose uvs are not leaf coordinates).
enum class Venation { kPinnate, kParallel, kNone };

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::kPlain;
  Eigen::Vector3f base_rgb{0.5f, 0.5f, 0.5f};    // linear 0..1
  Eigen::Vector3f detail_rgb{0.4f, 0.4f, 0.4f};  // veins, speckles, rim
  float variation = 0.1f;                        // amplitude of the low-frequency colour noise
  float detail_scale = 1.0f;  // texture frequency multiplier (per metre of uv for leaves)
  uint32_t seed = 0;
  // Leaves only.
  Venation venation = Venation::kPinnate;
  // Metres spanned by one unit of u and of v (a leaf: its length and its greatest half-width;
  // other materials have uvs in metres), so texture features keep a physical size.
  Eigen::Vector2f uv_extent{1.0f, 1.0f};
};

// Albedo (linear RGB, 0..1) of material at texture coordinate uv. A pure function of its
// arguments. For leaves u runs along the leaf (0 at the base, 1 at the tip) and v across it
// (-1..1, 0 on the midrib).
Eigen::Vector3f Albedo(const Material& material, const Eigen::Vector2f& uv);

}  // namespace avc::sim
