#pragma once

// The part of a simulated scan's ground truth the builder reconstructs: the plant's organs
// (stem, petioles, leaves). The automatic masks leave the pot and soil out on purpose.

#include "core/geometry/mesh.h"

namespace avc::bench {

// The faces labelled stem, petiole or leaf (every face when the mesh has no labels).
geometry::Mesh PlantOrgans(const geometry::Mesh& mesh);

}  // namespace avc::bench
