#include "sim/scene/mesh_scene.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "sim/scene/plant.h"
#include "sim/scene/plant_materials.h"
#include "sim/scene/pot.h"

namespace avc::sim {
namespace {

double ChooseScale(const geometry::Mesh& mesh, const MeshPlacement& placement) {
  if (!std::isfinite(placement.scale) || placement.scale < 0) {
    throw std::invalid_argument(
        fmt::format("MeshPlacement.scale is {}, expected >= 0 (0: fit "
                    "target_height)",
                    placement.scale));
  }
  if (placement.scale > 0) return placement.scale;
  if (!std::isfinite(placement.target_height) || placement.target_height <= 0) {
    throw std::invalid_argument(
        fmt::format("MeshPlacement.target_height is {}, expected > 0 when scale is 0",
                    placement.target_height));
  }
  Eigen::Vector3f min;
  Eigen::Vector3f max;
  geometry::Bounds(mesh, &min, &max);
  const double height = static_cast<double>(max.z()) - min.z();
  if (height <= 0) throw std::invalid_argument("mesh is flat in z: cannot fit a target height");
  return placement.target_height / height;
}

// Per-vertex uvs in metres by box mapping: each vertex is projected on the axis plane most
// facing its (area-weighted) normal; offsets keep the three projections from repeating.
std::vector<Eigen::Vector2f> BoxMappedUvs(const geometry::Mesh& mesh) {
  std::vector<Eigen::Vector3f> normals(mesh.vertices.size(), Eigen::Vector3f::Zero());
  for (const Eigen::Vector3i& f : mesh.faces) {
    const Eigen::Vector3f n = (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                                  .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]]);
    for (int k = 0; k < 3; ++k) normals[f[k]] += n;
  }
  std::vector<Eigen::Vector2f> uvs(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3f& p = mesh.vertices[i];
    const Eigen::Vector3f a = normals[i].cwiseAbs();
    if (a.x() >= a.y() && a.x() >= a.z()) {
      uvs[i] = {p.y() + 0.37f, p.z()};
    } else if (a.y() >= a.z()) {
      uvs[i] = {p.x(), p.z() + 0.61f};
    } else {
      uvs[i] = {p.x() + 0.23f, p.y() + 0.83f};
    }
  }
  return uvs;
}

}  // namespace

Scene SceneFromMesh(geometry::Mesh mesh, const MeshPlacement& placement) {
  const std::string problem = mesh.Validate();
  if (!problem.empty()) throw std::invalid_argument("SceneFromMesh: " + problem);
  if (mesh.faces.empty()) throw std::invalid_argument("SceneFromMesh: the mesh has no faces");
  if (placement.y_up) {
    // Rotate +90 degrees about x: +y becomes +z (and +z becomes -y), keeping handedness.
    for (Eigen::Vector3f& v : mesh.vertices) v = Eigen::Vector3f(v.x(), -v.z(), v.y());
  }
  const double scale = ChooseScale(mesh, placement);

  // Scale about the bottom centre of the bounding box, then lift onto the soil.
  Eigen::Vector3f min;
  Eigen::Vector3f max;
  geometry::Bounds(mesh, &min, &max);
  const Eigen::Vector3d anchor(0.5 * (double{min.x()} + max.x()), 0.5 * (double{min.y()} + max.y()),
                               min.z());
  const double ground = placement.with_pot ? SoilHeight() : 0.0;
  for (Eigen::Vector3f& v : mesh.vertices) {
    const Eigen::Vector3d p = (v.cast<double>() - anchor) * scale;
    v = Eigen::Vector3f(static_cast<float>(p.x()), static_cast<float>(p.y()),
                        static_cast<float>(p.z() + ground));
  }
  geometry::Bounds(mesh, &min, &max);
  const Eigen::Vector3f size = max - min;

  Scene scene;
  scene.name = placement.name;
  PlantRandom random(placement.seed ^ 0x9e3779b9u);
  PlantPlan look;  // default leaf and stem colours
  scene.materials.push_back(PotMaterial(placement.seed));
  scene.materials.push_back(SoilMaterial(placement.seed));
  scene.materials.push_back(StemMaterial("stem", look.stem_rgb, random.Bits()));
  scene.materials.push_back(StemMaterial("petiole", look.stem_rgb * 1.15f, random.Bits()));

  if (mesh.face_labels.empty()) mesh.face_labels.assign(mesh.faces.size(), placement.label);
  // One leaf material per leaf label, in label order.
  std::map<int32_t, int32_t> leaf_materials;
  for (int32_t label : mesh.face_labels) {
    if (geometry::labels::IsLeaf(label)) leaf_materials.emplace(label, 0);
  }
  if (leaf_materials.empty()) leaf_materials.emplace(geometry::labels::kLeafBase, 0);
  const bool generated_uvs = mesh.uvs.empty();
  if (generated_uvs) mesh.uvs = BoxMappedUvs(mesh);
  for (auto& [label, material] : leaf_materials) {
    material = static_cast<int32_t>(scene.materials.size());
    LeafSpec leaf;
    leaf.length = generated_uvs ? 1.0f : std::max(size.x(), size.z());
    leaf.half_width = generated_uvs ? 1.0f : std::max(size.y(), size.z());
    Material m = LeafMaterial(look, leaf, label - geometry::labels::kLeafBase, random);
    m.venation = Venation::kNone;  // these uvs are not leaf coordinates
    scene.materials.push_back(m);
  }
  const int32_t default_material = leaf_materials.begin()->second;
  mesh.face_materials.resize(mesh.faces.size());
  for (size_t i = 0; i < mesh.faces.size(); ++i) {
    const int32_t label = mesh.face_labels[i];
    int32_t material = default_material;
    if (label == geometry::labels::kPot) material = kPotMaterial;
    if (label == geometry::labels::kSoil) material = kSoilMaterial;
    if (label == geometry::labels::kStem) material = kStemMaterial;
    if (label == geometry::labels::kPetiole) material = kPetioleMaterial;
    if (geometry::labels::IsLeaf(label)) material = leaf_materials.at(label);
    mesh.face_materials[i] = material;
  }

  if (placement.with_pot) {
    AppendPotAndSoil(ResolutionFor(32, 0.5f), placement.seed, kPotMaterial, kSoilMaterial,
                     &scene.mesh);
  }
  scene.mesh.Append(mesh);
  return scene;
}

}  // namespace avc::sim
