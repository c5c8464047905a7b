#pragma once

// A simulated scene: one mesh (plant, pot, soil) in the world frame (the turntable's frame,
// z up, origin on the turntable axis at the table top) with per-face organ labels and
// materials, plus the materials themselves.

#include <string>
#include <vector>

#include "core/geometry/mesh.h"
#include "sim/scene/material.h"

namespace avc::sim {

struct Scene {
  std::string name;     // e.g. "rosette seed 7"
  geometry::Mesh mesh;  // uvs, face_labels and face_materials are filled
  std::vector<Material> materials;
};

}  // namespace avc::sim
