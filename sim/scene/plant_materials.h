#pragma once

// Realistic colours (linear RGB) for the organs of generated and loaded plants.

#include <cstdint>
#include <string>

#include "sim/scene/material.h"
#include "sim/scene/plant_plan.h"
#include "sim/scene/plant_random.h"

namespace avc::sim {

// Terracotta or dark grey plastic, chosen by the seed.
Material PotMaterial(uint32_t seed);
Material SoilMaterial(uint32_t seed);
Material StemMaterial(std::string name, const Eigen::Vector3f& rgb, uint32_t seed);
// A leaf of the plan's species: its green varies per leaf (brightness, yellowness), younger
// leaves are lighter; uv_extent follows the leaf's size so veins and speckle keep their size.
Material LeafMaterial(const PlantPlan& plan, const LeafSpec& leaf, int index, PlantRandom& random);

}  // namespace avc::sim
