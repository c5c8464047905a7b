#include "bench/mvs/plant_organs.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

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

TruthTraits MeasureTruthTraits(const geometry::Mesh& mesh) {
  TruthTraits truth;
  const geometry::Mesh organs = PlantOrgans(mesh);
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (size_t f = 0; f < organs.faces.size(); ++f) {
    const Eigen::Vector3i& t = organs.faces[f];
    for (int k = 0; k < 3; ++k) {
      low = std::min(low, static_cast<double>(organs.vertices[t[k]].z()));
      high = std::max(high, static_cast<double>(organs.vertices[t[k]].z()));
    }
    if (organs.face_labels.empty() || !geometry::labels::IsLeaf(organs.face_labels[f])) continue;
    truth.leaf_area += geometry::FaceArea(organs, t);
  }
  double soil = 0.0;
  size_t soil_corners = 0;
  for (size_t f = 0; f < mesh.faces.size() && f < mesh.face_labels.size(); ++f) {
    if (mesh.face_labels[f] != geometry::labels::kSoil) continue;
    for (int k = 0; k < 3; ++k) soil += mesh.vertices[mesh.faces[f][k]].z();
    soil_corners += 3;
  }
  const double ground = soil_corners > 0 ? soil / static_cast<double>(soil_corners) : low;
  truth.ground_z = ground;
  truth.height = high > ground ? high - ground : 0.0;
  return truth;
}

}  // namespace avc::bench
