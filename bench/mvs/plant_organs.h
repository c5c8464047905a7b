#pragma once

// The part of a simulated scan's ground truth the builder reconstructs: the plant's organs
// (stem, petioles, leaves). The automatic masks leave the pot and soil out on purpose.

#include "core/geometry/mesh.h"

namespace avc::bench {

// The faces labelled stem, petiole or leaf (every face when the mesh has no labels).
geometry::Mesh PlantOrgans(const geometry::Mesh& mesh);

// What the traits of a reconstruction of the plant should measure: the leaves' one-sided area
// (m^2, faces with a leaf label) and the height of the organs (m, their highest vertex above
// their lowest, as the traits measure a mesh without a ground height). organs: PlantOrgans.
struct TruthTraits {
  double leaf_area = 0;
  double height = 0;
};
TruthTraits MeasureTruthTraits(const geometry::Mesh& organs);

}  // namespace avc::bench
