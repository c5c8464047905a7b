// External meshes placed on the turntable: scale, centring, resting on the soil, labels,
// materials and generated uvs; real meshes from shared/data when present.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "core/geometry/mesh_io.h"
#include "sim/scene/mesh_scene.h"
#include "sim/scene/phenomenal_plant.h"
#include "sim/scene/plant.h"
#include "sim/scene/pot.h"
#include "tests/support/test_support.h"

namespace avc::sim {
namespace {

namespace labels = geometry::labels;

std::filesystem::path SharedData() { return avc::testing::SharedDataDir(); }

// An axis-aligned box (closed, 12 triangles) off-centre, in millimetres.
geometry::Mesh BoxMesh(const Eigen::Vector3f& min, const Eigen::Vector3f& max) {
  geometry::Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back(i & 1 ? max.x() : min.x(), i & 2 ? max.y() : min.y(),
                               i & 4 ? max.z() : min.z());
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.faces.emplace_back(q[0], q[1], q[2]);
    mesh.faces.emplace_back(q[0], q[2], q[3]);
  }
  return mesh;
}

// Bounds of the faces with a leaf label (the placed mesh).
void PlacedBounds(const Scene& scene, Eigen::Vector3f* min, Eigen::Vector3f* max) {
  *min = Eigen::Vector3f::Constant(1e9f);
  *max = Eigen::Vector3f::Constant(-1e9f);
  for (size_t f = 0; f < scene.mesh.faces.size(); ++f) {
    const int32_t label = scene.mesh.face_labels[f];
    if (label == labels::kPot || label == labels::kSoil) continue;
    for (int k = 0; k < 3; ++k) {
      *min = min->cwiseMin(scene.mesh.vertices[scene.mesh.faces[f][k]]);
      *max = max->cwiseMax(scene.mesh.vertices[scene.mesh.faces[f][k]]);
    }
  }
}

TEST(SceneFromMesh, FitsTheTargetHeightOnTheSoilOnTheAxis) {
  MeshPlacement placement;
  placement.target_height = 0.2;
  const Scene scene = SceneFromMesh(BoxMesh({100, 50, 30}, {140, 60, 530}), placement);
  EXPECT_EQ(scene.mesh.Validate(), "");
  Eigen::Vector3f min, max;
  PlacedBounds(scene, &min, &max);
  EXPECT_NEAR(max.z() - min.z(), 0.2f, 1e-5f);
  EXPECT_NEAR(min.z(), SoilHeight(), 1e-6f);
  EXPECT_NEAR(min.x() + max.x(), 0.0f, 1e-6f);
  EXPECT_NEAR(min.y() + max.y(), 0.0f, 1e-6f);
  EXPECT_NEAR(max.x() - min.x(), 0.2f * 40 / 500, 1e-5f);
  // Pot, soil and the mesh as one leaf, each face with the material of its organ.
  std::set<int32_t> seen(scene.mesh.face_labels.begin(), scene.mesh.face_labels.end());
  EXPECT_EQ(seen, (std::set<int32_t>{labels::kPot, labels::kSoil, labels::kLeafBase}));
  for (size_t f = 0; f < scene.mesh.faces.size(); ++f) {
    const Material& m = scene.materials.at(scene.mesh.face_materials[f]);
    if (labels::IsLeaf(scene.mesh.face_labels[f])) {
      EXPECT_EQ(m.kind, MaterialKind::kLeaf);
    } else if (scene.mesh.face_labels[f] == labels::kPot) {
      EXPECT_EQ(m.kind, MaterialKind::kPot);
    }
  }
  EXPECT_EQ(scene.mesh.uvs.size(), scene.mesh.vertices.size());
}

TEST(SceneFromMesh, ExplicitScaleWithoutPotRestsOnTheTurntable) {
  MeshPlacement placement;
  placement.scale = 0.001;
  placement.with_pot = false;
  placement.label = labels::kStem;
  const Scene scene = SceneFromMesh(BoxMesh({-10, -10, -40}, {10, 10, 140}), placement);
  Eigen::Vector3f min, max;
  geometry::Bounds(scene.mesh, &min, &max);
  EXPECT_NEAR(min.z(), 0.0f, 1e-7f);
  EXPECT_NEAR(max.z(), 0.18f, 1e-6f);
  EXPECT_EQ(scene.mesh.num_faces(), 12u);
  for (int32_t label : scene.mesh.face_labels) EXPECT_EQ(label, labels::kStem);
  for (int32_t material : scene.mesh.face_materials) EXPECT_EQ(material, kStemMaterial);
}

TEST(SceneFromMesh, KeepsLabelsAndUvsTheMeshCarries) {
  // A generated plant written to PLY and placed again keeps its organs, one material per leaf.
  const Scene plant = GeneratePlant(PlantPreset::kBroadleaf, 4, PlantOptions{.leaf_segments = 6});
  MeshPlacement placement;
  placement.with_pot = false;
  placement.scale = 1.0;
  const Scene scene = SceneFromMesh(plant.mesh, placement);
  EXPECT_EQ(scene.mesh.face_labels, plant.mesh.face_labels);
  EXPECT_EQ(scene.mesh.uvs, plant.mesh.uvs);
  std::set<int32_t> leaf_materials;
  for (size_t f = 0; f < scene.mesh.faces.size(); ++f) {
    if (labels::IsLeaf(scene.mesh.face_labels[f])) {
      leaf_materials.insert(scene.mesh.face_materials[f]);
    }
  }
  EXPECT_EQ(leaf_materials.size(), plant.materials.size() - kFirstLeafMaterial);
  EXPECT_EQ(scene.materials.size(), plant.materials.size());
}

TEST(SceneFromMesh, YUpMeshesAreTurnedUpright) {
  MeshPlacement placement;
  placement.scale = 0.001;
  placement.with_pot = false;
  placement.y_up = true;
  // 20 mm wide, 300 mm tall along +y, 40 mm deep.
  const Scene scene = SceneFromMesh(BoxMesh({0, 0, 0}, {20, 300, 40}), placement);
  Eigen::Vector3f min, max;
  geometry::Bounds(scene.mesh, &min, &max);
  EXPECT_NEAR(max.z() - min.z(), 0.3f, 1e-6f);
  EXPECT_NEAR(max.x() - min.x(), 0.02f, 1e-6f);
  EXPECT_NEAR(max.y() - min.y(), 0.04f, 1e-6f);
  // Still outward facing: a right-handed rotation keeps the winding's meaning.
  EXPECT_GT(geometry::SurfaceArea(scene.mesh), 0.0);
}

TEST(SceneFromMesh, BadInputIsRejected) {
  EXPECT_THROW(SceneFromMesh(geometry::Mesh{}), std::invalid_argument);
  MeshPlacement negative;
  negative.scale = -1;
  EXPECT_THROW(SceneFromMesh(BoxMesh({0, 0, 0}, {1, 1, 1}), negative), std::invalid_argument);
  MeshPlacement no_height;
  no_height.target_height = 0;
  EXPECT_THROW(SceneFromMesh(BoxMesh({0, 0, 0}, {1, 1, 1}), no_height), std::invalid_argument);
  geometry::Mesh broken = BoxMesh({0, 0, 0}, {1, 1, 1});
  broken.faces[3] = Eigen::Vector3i(0, 1, 8);
  EXPECT_THROW(SceneFromMesh(broken), std::invalid_argument);
  geometry::Mesh flat = BoxMesh({0, 0, 0}, {1, 1, 0});
  EXPECT_THROW(SceneFromMesh(flat), std::invalid_argument);
}

TEST(SceneFromMesh, RealMeshesFromSharedData) {
  const std::filesystem::path maize =
      SharedData() / "maize_phenoarch/examples_data/synthetic_plant_1/synthetic_plant.ply";
  const std::filesystem::path bunny = SharedData() / "meshes/cgal/bunny00.off";
  if (!std::filesystem::exists(maize) || !std::filesystem::exists(bunny)) {
    GTEST_SKIP() << "shared data absent under " << SharedData();
  }
  // The synthetic maize is in millimetres: 179.025 mm tall from its lowest to highest point.
  MeshPlacement millimetres;
  millimetres.scale = 0.001;
  const Scene plant = SceneFromMesh(geometry::ReadMesh(maize), millimetres);
  EXPECT_EQ(plant.mesh.Validate(), "");
  Eigen::Vector3f min, max;
  PlacedBounds(plant, &min, &max);
  EXPECT_NEAR(max.z() - min.z(), 0.179025f, 1e-5f);
  EXPECT_NEAR(min.z(), SoilHeight(), 1e-6f);

  MeshPlacement fit;
  fit.target_height = 0.15;
  fit.seed = 3;
  const Scene scene = SceneFromMesh(geometry::ReadMesh(bunny), fit);
  EXPECT_EQ(scene.mesh.Validate(), "");
  PlacedBounds(scene, &min, &max);
  EXPECT_NEAR(max.z() - min.z(), 0.15f, 1e-5f);
  // Box-mapped uvs vary over the surface, so the texture is not smeared.
  const geometry::Mesh& mesh = scene.mesh;
  double spread = 0;
  for (const Eigen::Vector3i& f : mesh.faces) spread += (mesh.uvs[f[1]] - mesh.uvs[f[0]]).norm();
  EXPECT_GT(spread / static_cast<double>(mesh.faces.size()), 1e-4);
}

TEST(PhenomenalPlant, FolderGivesPerLeafLabelsOfTheSyntheticMaize) {
  const std::filesystem::path folder =
      SharedData() / "maize_phenoarch/examples_data/synthetic_plant_1";
  if (!std::filesystem::exists(folder)) GTEST_SKIP() << "shared data absent: " << folder;
  const geometry::Mesh mesh = ReadPhenomenalPlant(folder);
  EXPECT_EQ(mesh.Validate(), "");
  ASSERT_EQ(mesh.num_faces(), 11922u);
  std::map<int32_t, size_t> faces_per_label;
  for (int32_t label : mesh.face_labels) ++faces_per_label[label];
  ASSERT_EQ(faces_per_label.size(), 16u);  // the stem and 15 leaves
  EXPECT_TRUE(faces_per_label.count(labels::kStem));
  EXPECT_TRUE(faces_per_label.count(labels::kLeafBase + 14));
  EXPECT_GT(faces_per_label[labels::kStem], 11922u / 100);
  EXPECT_LT(faces_per_label[labels::kStem], 11922u / 2);
  // Leaf tips (last points of the JSON leaf polylines, mm) lie on faces of their own leaf.
  const std::pair<int, Eigen::Vector3f> tips[] = {{0, {11.73f, -0.26f, 0.38f}},
                                                  {7, {-58.04f, -36.69f, 69.57f}},
                                                  {14, {23.44f, 4.58f, 175.41f}}};
  for (const auto& [leaf, tip] : tips) {
    size_t nearest = 0;
    float nearest_distance = 1e9f;
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      const Eigen::Vector3i& t = mesh.faces[f];
      const Eigen::Vector3f centroid =
          (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0f;
      if ((centroid - tip).norm() < nearest_distance) {
        nearest_distance = (centroid - tip).norm();
        nearest = f;
      }
    }
    EXPECT_LT(nearest_distance, 10.0f) << "leaf " << leaf;  // the tips have coarse faces
    EXPECT_EQ(mesh.face_labels[nearest], labels::kLeafBase + leaf);
  }
  // On the turntable: one leaf material per leaf.
  MeshPlacement millimetres;
  millimetres.scale = 0.001;
  const Scene scene = SceneFromMesh(mesh, millimetres);
  EXPECT_EQ(scene.materials.size(), static_cast<size_t>(kFirstLeafMaterial + 15));

  try {
    ReadPhenomenalPlant(folder / "missing");
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("synthetic_plant.ply"), std::string::npos);
  }
}

}  // namespace
}  // namespace avc::sim
