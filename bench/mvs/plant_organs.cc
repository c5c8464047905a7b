#include "bench/mvs/plant_organs.h"

namespace avc::bench {

geometry::Mesh PlantOrgans(const geometry::Mesh& mesh) {
  geometry::Mesh plant;
  plant.vertices = mesh.vertices;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const int32_t label =
        mesh.face_labels.empty() ? geometry::labels::kLeafBase : mesh.face_labels[f];
    if (label == geometry::labels::kStem || label == geometry::labels::kPetiole ||
        geometry::labels::IsLeaf(label)) {
      plant.faces.push_back(mesh.faces[f]);
      if (!mesh.face_labels.empty()) plant.face_labels.push_back(label);
    }
  }
  return plant;
}

}  // namespace avc::bench
