#pragma once

// The synthetic plants shipped with openalea/phenomenal (PhenoArch examples): a folder with
// synthetic_plant.ply (a closed mesh, millimetres) and synthetic_plant.json (the stem and one
// polyline per leaf, points x y z width). Reading the folder gives the mesh with per-face organ
// labels, so a scene built from it (SceneFromMesh, scale 0.001) has per-leaf ground truth.

#include <filesystem>

#include "core/geometry/mesh.h"

namespace avc::sim {

// Faces are labelled by the nearest organ skeleton (distance to the polyline less half its local
// width): kStem, or kLeafBase + i for the i-th leaf polyline. Units stay those of the files
// (millimetres). Throws std::runtime_error naming the file on a missing or malformed file.
geometry::Mesh ReadPhenomenalPlant(const std::filesystem::path& folder);

}  // namespace avc::sim
