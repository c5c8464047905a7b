#pragma once

// The pot and its soil: a tapered open pot with a rim, 15 cm across the rim, standing on the
// turntable top (z = 0), and a slightly uneven soil disc just below the rim.

#include <cstddef>
#include <cstdint>

#include "core/geometry/mesh.h"
#include "sim/scene/organ_mesh.h"

namespace avc::sim {

// Height of the soil surface on the axis (metres above the turntable): where plants stand.
float SoilHeight();
// Outer radius of the pot rim (metres).
float PotRimRadius();

size_t PotTriangles(const MeshResolution& resolution);

// Appends the pot (label kPot, material pot_material) and soil (kSoil, soil_material). seed
// shapes the soil's small unevenness. Pot uvs are metres (around, along the wall profile); soil
// uvs are metres (x, y).
void AppendPotAndSoil(const MeshResolution& resolution, uint32_t seed, int32_t pot_material,
                      int32_t soil_material, geometry::Mesh* mesh);

}  // namespace avc::sim
