#pragma once

// The part of a simulated scan's ground truth the builder reconstructs: the plant's organs
// (stem, petioles, leaves). The automatic masks leave the pot and soil out on purpose.

#include "core/geometry/mesh.h"

namespace avc::bench {

// The faces labelled stem, petiole or leaf (every face when the mesh has no labels).
geometry::Mesh PlantOrgans(const geometry::Mesh& mesh);

// What the traits of a reconstruction of the plant should measure: the leaves' one-sided area
// (m^2, faces with a leaf label) and the plant's height (m): its organs' highest vertex above
// the soil's surface (the mean height of the soil's vertices; the simulated stems start 1 cm
// under it), or above the organs' lowest vertex when there is no soil. mesh: a simulated
// scan's whole ground truth, with face labels.
struct TruthTraits {
  double leaf_area = 0;
  double height = 0;
  double ground_z = 0;  // m, world: what the height is measured from
};
TruthTraits MeasureTruthTraits(const geometry::Mesh& mesh);

}  // namespace avc::bench
