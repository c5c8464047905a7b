#pragma once

// Meshing of planned organs: leaves as single open sheets with leaf uvs, stems and petioles as
// tubes. Triangle counts are known in advance so a resolution can be chosen for a target count.

#include <cstddef>
#include <cstdint>

#include "core/geometry/mesh.h"
#include "sim/scene/plant_plan.h"

namespace avc::sim {

struct MeshResolution {
  int leaf_along = 24;      // segments along a leaf
  int leaf_across = 12;     // segments across a leaf (even: the midrib is a vertex line)
  int tube_around = 8;      // segments around a stem or petiole
  float tube_step = 0.01f;  // metres between tube rings
  int pot_around = 96;      // segments around the pot and the soil
  int soil_rings = 12;      // rings of the soil disc
};

// The resolution that follows from leaf_segments (segments along each leaf).
MeshResolution ResolutionFor(int leaf_segments, float leaf_across_ratio);

size_t LeafTriangles(const MeshResolution& resolution);
size_t TubeTriangles(const TubeSpec& tube, const MeshResolution& resolution);

// Appends a leaf translated by offset; faces get label and material. uv: u 0 (base) .. 1 (tip),
// v -1..1 across (0 on the midrib). Faces are counter-clockwise seen from the upper side.
void AppendLeaf(const LeafSpec& leaf, const Eigen::Vector3f& offset,
                const MeshResolution& resolution, int32_t label, int32_t material,
                geometry::Mesh* mesh);

// Appends a tube (open at the base, closed by a small cone at the end) translated by offset,
// outward facing. uv in metres: (around, along).
void AppendTube(const TubeSpec& tube, const Eigen::Vector3f& offset,
                const MeshResolution& resolution, int32_t material, geometry::Mesh* mesh);

}  // namespace avc::sim
