// The procedural plant generator: determinism, validity, organ labels, realistic size, triangle
// budget, leaves as open connected sheets that bend, fold and touch each other.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cstring>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>

#include "sim/scene/plant.h"
#include "sim/scene/pot.h"

namespace avc::sim {
namespace {

namespace labels = geometry::labels;

std::map<int32_t, std::vector<size_t>> FacesByLabel(const geometry::Mesh& mesh) {
  std::map<int32_t, std::vector<size_t>> faces;
  for (size_t i = 0; i < mesh.faces.size(); ++i) faces[mesh.face_labels[i]].push_back(i);
  return faces;
}

struct Box {
  Eigen::Vector3f min = Eigen::Vector3f::Constant(1e9f);
  Eigen::Vector3f max = Eigen::Vector3f::Constant(-1e9f);
  bool Intersects(const Box& other) const {
    return (min.array() <= other.max.array()).all() && (other.min.array() <= max.array()).all();
  }
};

Box FacesBox(const geometry::Mesh& mesh, const std::vector<size_t>& faces) {
  Box box;
  for (size_t f : faces) {
    for (int k = 0; k < 3; ++k) {
      box.min = box.min.cwiseMin(mesh.vertices[mesh.faces[f][k]]);
      box.max = box.max.cwiseMax(mesh.vertices[mesh.faces[f][k]]);
    }
  }
  return box;
}

int FindRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

TEST(PlantGenerator, SameSeedGivesBitIdenticalPlant) {
  for (PlantPreset preset : AllPresets()) {
    const Scene a = GeneratePlant(preset, 7);
    const Scene b = GeneratePlant(preset, 7);
    ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size()) << PresetName(preset);
    EXPECT_EQ(std::memcmp(a.mesh.vertices.data(), b.mesh.vertices.data(),
                          a.mesh.vertices.size() * sizeof(Eigen::Vector3f)),
              0)
        << PresetName(preset);
    EXPECT_EQ(std::memcmp(a.mesh.uvs.data(), b.mesh.uvs.data(),
                          a.mesh.uvs.size() * sizeof(Eigen::Vector2f)),
              0);
    EXPECT_EQ(a.mesh.faces, b.mesh.faces);
    EXPECT_EQ(a.mesh.face_labels, b.mesh.face_labels);
    EXPECT_EQ(a.mesh.face_materials, b.mesh.face_materials);
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
      EXPECT_EQ(a.materials[i].base_rgb, b.materials[i].base_rgb);
      EXPECT_EQ(a.materials[i].seed, b.materials[i].seed);
    }
    EXPECT_EQ(a.name, std::string(PresetName(preset)) + " seed 7");
  }
}

TEST(PlantGenerator, DifferentSeedsGiveDifferentPlants) {
  for (PlantPreset preset : AllPresets()) {
    const Scene a = GeneratePlant(preset, 1);
    const Scene b = GeneratePlant(preset, 2);
    // Compare the leaves' extent: a different plant moves leaves by centimetres.
    Eigen::Vector3f a_min, a_max, b_min, b_max;
    geometry::Bounds(a.mesh, &a_min, &a_max);
    geometry::Bounds(b.mesh, &b_min, &b_max);
    const float difference =
        (a_min - b_min).cwiseAbs().maxCoeff() + (a_max - b_max).cwiseAbs().maxCoeff();
    EXPECT_GT(difference, 0.01f) << PresetName(preset);
  }
}

TEST(PlantGenerator, EveryPresetIsValidWithItsOrgans) {
  // Leaf counts of each preset's morphology.
  const std::map<PlantPreset, std::pair<int, int>> leaf_range = {{PlantPreset::kRosette, {16, 22}},
                                                                 {PlantPreset::kBroadleaf, {8, 11}},
                                                                 {PlantPreset::kStrap, {10, 14}},
                                                                 {PlantPreset::kBushy, {30, 120}}};
  for (PlantPreset preset : AllPresets()) {
    for (uint32_t seed : {3u, 11u}) {
      const Scene scene = GeneratePlant(preset, seed);
      const geometry::Mesh& mesh = scene.mesh;
      SCOPED_TRACE(scene.name);
      EXPECT_EQ(mesh.Validate(), "");
      ASSERT_EQ(mesh.uvs.size(), mesh.vertices.size());
      ASSERT_EQ(mesh.face_labels.size(), mesh.faces.size());
      ASSERT_EQ(mesh.face_materials.size(), mesh.faces.size());
      const auto by_label = FacesByLabel(mesh);
      EXPECT_TRUE(by_label.count(labels::kPot));
      EXPECT_TRUE(by_label.count(labels::kSoil));
      EXPECT_TRUE(by_label.count(labels::kStem));
      const bool petioles = preset == PlantPreset::kBroadleaf || preset == PlantPreset::kBushy;
      EXPECT_EQ(by_label.count(labels::kPetiole) == 1, petioles);
      // Leaves are labelled kLeafBase + 0..n-1 and each has its own leaf material.
      int leaves = 0;
      for (const auto& [label, faces] : by_label) {
        if (!labels::IsLeaf(label)) continue;
        EXPECT_EQ(label, labels::kLeafBase + leaves);
        const int32_t material = mesh.face_materials[faces.front()];
        EXPECT_EQ(material, kFirstLeafMaterial + leaves);
        EXPECT_EQ(scene.materials[material].kind, MaterialKind::kLeaf);
        ++leaves;
      }
      EXPECT_GE(leaves, leaf_range.at(preset).first);
      EXPECT_LE(leaves, leaf_range.at(preset).second);
      EXPECT_EQ(scene.materials.size(), static_cast<size_t>(kFirstLeafMaterial + leaves));
      const std::map<int32_t, int32_t> organ_material = {{labels::kPot, kPotMaterial},
                                                         {labels::kSoil, kSoilMaterial},
                                                         {labels::kStem, kStemMaterial},
                                                         {labels::kPetiole, kPetioleMaterial}};
      for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const int32_t material = mesh.face_materials[f];
        ASSERT_LT(static_cast<size_t>(material), scene.materials.size());
        if (auto it = organ_material.find(mesh.face_labels[f]); it != organ_material.end()) {
          EXPECT_EQ(material, it->second);
        }
      }
    }
  }
}

TEST(PlantGenerator, SizesAreRealistic) {
  for (PlantPreset preset : AllPresets()) {
    const Scene scene = GeneratePlant(preset, 5);
    SCOPED_TRACE(scene.name);
    const auto by_label = FacesByLabel(scene.mesh);
    // The pot: 15 cm across the rim, standing on z = 0.
    const Box pot = FacesBox(scene.mesh, by_label.at(labels::kPot));
    EXPECT_NEAR(pot.max.x() - pot.min.x(), 0.152f, 0.003f);
    EXPECT_NEAR(pot.min.z(), 0.0f, 1e-6f);
    EXPECT_NEAR(pot.max.z(), 0.132f, 0.002f);
    const Box soil = FacesBox(scene.mesh, by_label.at(labels::kSoil));
    EXPECT_NEAR(soil.min.z(), SoilHeight(), 0.003f);
    // The plant: tens of centimetres, nothing below the turntable.
    Box plant;
    for (const auto& [label, faces] : by_label) {
      if (label == labels::kPot || label == labels::kSoil) continue;
      const Box box = FacesBox(scene.mesh, faces);
      plant.min = plant.min.cwiseMin(box.min);
      plant.max = plant.max.cwiseMax(box.max);
    }
    EXPECT_GT(plant.min.z(), 0.0f);
    const float height = plant.max.z() - SoilHeight();
    EXPECT_GT(height, 0.12f);
    EXPECT_LT(height, 0.5f);
    const float spread = std::max(plant.max.x() - plant.min.x(), plant.max.y() - plant.min.y());
    EXPECT_GT(spread, 0.15f);
    EXPECT_LT(spread, 0.8f);
    // Rooted on the axis: the lowest stem point is within 2 cm of it, inside the soil.
    Eigen::Vector3f root = Eigen::Vector3f::Constant(1e9f);
    for (size_t f : by_label.at(labels::kStem)) {
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3f& p = scene.mesh.vertices[scene.mesh.faces[f][k]];
        if (p.z() < root.z()) root = p;
      }
    }
    EXPECT_LT(root.head<2>().norm(), 0.02f);
    EXPECT_LT(root.z(), SoilHeight());
  }
}

TEST(PlantGenerator, TriangleCountFollowsTheResolutionOptions) {
  for (PlantPreset preset : AllPresets()) {
    const size_t default_count = GeneratePlant(preset, 9).mesh.num_faces();
    EXPECT_GT(default_count, 20000u) << PresetName(preset);
    EXPECT_LT(default_count, 60000u) << PresetName(preset);
    EXPECT_NEAR(static_cast<double>(default_count), 40000.0, 1000.0) << PresetName(preset);
    PlantOptions benchmark;
    benchmark.target_triangles = 100000;
    EXPECT_NEAR(static_cast<double>(GeneratePlant(preset, 9, benchmark).mesh.num_faces()), 100000.0,
                1500.0)
        << PresetName(preset);
  }
  // leaf_segments fixes the grid of every leaf.
  PlantOptions fixed;
  fixed.leaf_segments = 10;
  const Scene scene = GeneratePlant(PlantPreset::kStrap, 9, fixed);
  const auto by_label = FacesByLabel(scene.mesh);
  const size_t leaf_faces = by_label.at(labels::kLeafBase).size();
  EXPECT_EQ(leaf_faces, 2u * 10u * 4u);  // 10 along, 4 across (the minimum)
  PlantOptions finer;
  finer.leaf_segments = 40;
  EXPECT_EQ(
      FacesByLabel(GeneratePlant(PlantPreset::kStrap, 9, finer).mesh).at(labels::kLeafBase).size(),
      2u * 40u * 12u);
}

TEST(PlantGenerator, LeavesAreOpenConnectedSheetsWithLeafUvs) {
  for (PlantPreset preset : AllPresets()) {
    const Scene scene = GeneratePlant(preset, 4);
    const geometry::Mesh& mesh = scene.mesh;
    SCOPED_TRACE(scene.name);
    for (const auto& [label, faces] : FacesByLabel(mesh)) {
      if (!labels::IsLeaf(label)) continue;
      std::map<std::pair<int, int>, int> edge_uses;
      std::vector<int> parent(mesh.vertices.size());
      std::iota(parent.begin(), parent.end(), 0);
      std::set<int> vertices;
      for (size_t f : faces) {
        for (int k = 0; k < 3; ++k) {
          const int a = mesh.faces[f][k];
          const int b = mesh.faces[f][(k + 1) % 3];
          ++edge_uses[{std::min(a, b), std::max(a, b)}];
          parent[FindRoot(parent, a)] = FindRoot(parent, b);
          vertices.insert(a);
        }
      }
      int boundary = 0;
      for (const auto& [edge, uses] : edge_uses) {
        EXPECT_LE(uses, 2);  // a manifold sheet
        boundary += uses == 1;
      }
      EXPECT_GT(boundary, 0) << "leaf " << label << " is closed";
      std::set<int> components;
      for (int v : vertices) components.insert(FindRoot(parent, v));
      EXPECT_EQ(components.size(), 1u) << "leaf " << label;
      // uv: u from 0 (base) to 1 (tip), v from -1 to 1 across.
      float u_min = 1, u_max = 0, v_min = 1, v_max = -1;
      for (int v : vertices) {
        u_min = std::min(u_min, mesh.uvs[v].x());
        u_max = std::max(u_max, mesh.uvs[v].x());
        v_min = std::min(v_min, mesh.uvs[v].y());
        v_max = std::max(v_max, mesh.uvs[v].y());
      }
      EXPECT_FLOAT_EQ(u_min, 0.0f);
      EXPECT_FLOAT_EQ(u_max, 1.0f);
      EXPECT_FLOAT_EQ(v_min, -1.0f);
      EXPECT_FLOAT_EQ(v_max, 1.0f);
    }
  }
}

TEST(PlantGenerator, LeavesBendFoldAndRiseFromTheirBase) {
  // Outer rosette leaves: curved and folded (far from any plane), the base nearer the axis than
  // the tip, the upper side (counter-clockwise faces) facing up near the base.
  const Scene scene = GeneratePlant(PlantPreset::kRosette, 12);
  const geometry::Mesh& mesh = scene.mesh;
  const auto by_label = FacesByLabel(mesh);
  for (int leaf = 0; leaf < 5; ++leaf) {
    const auto& faces = by_label.at(labels::kLeafBase + leaf);
    std::set<int> vertices;
    for (size_t f : faces) {
      for (int k = 0; k < 3; ++k) vertices.insert(mesh.faces[f][k]);
    }
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : vertices) mean += mesh.vertices[v].cast<double>();
    mean /= static_cast<double>(vertices.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    Eigen::Vector3f base_point = Eigen::Vector3f::Zero(), tip_point = Eigen::Vector3f::Zero();
    for (int v : vertices) {
      const Eigen::Vector3d d = mesh.vertices[v].cast<double>() - mean;
      covariance += d * d.transpose();
      if (mesh.uvs[v] == Eigen::Vector2f(0, 0)) base_point = mesh.vertices[v];
      if (mesh.uvs[v] == Eigen::Vector2f(1, 0)) tip_point = mesh.vertices[v];
    }
    covariance /= static_cast<double>(vertices.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    EXPECT_GT(std::sqrt(solver.eigenvalues()[0]), 0.005) << "leaf " << leaf << " is flat";
    EXPECT_LT(base_point.head<2>().norm() + 0.1f, tip_point.head<2>().norm());
    Eigen::Vector3f base_normal = Eigen::Vector3f::Zero();
    for (size_t f : faces) {
      const Eigen::Vector3i& t = mesh.faces[f];
      if (mesh.uvs[t[0]].x() > 0.2f) continue;
      base_normal += (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                         .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    }
    EXPECT_GT(base_normal.normalized().z(), 0.2f) << "leaf " << leaf;
  }
}

TEST(PlantGenerator, LeavesTouchOrOverlapLikeRealPlants) {
  for (PlantPreset preset : AllPresets()) {
    const Scene scene = GeneratePlant(preset, 8);
    std::vector<Box> leaves;
    for (const auto& [label, faces] : FacesByLabel(scene.mesh)) {
      if (labels::IsLeaf(label)) leaves.push_back(FacesBox(scene.mesh, faces));
    }
    int touching = 0;
    for (size_t i = 0; i < leaves.size(); ++i) {
      for (size_t j = i + 1; j < leaves.size(); ++j) touching += leaves[i].Intersects(leaves[j]);
    }
    EXPECT_GE(touching, static_cast<int>(leaves.size()) / 2) << PresetName(preset);
  }
}

TEST(PlantGenerator, WithoutPotThePlantStandsOnTheTurntable) {
  PlantOptions options;
  options.with_pot = false;
  const Scene scene = GeneratePlant(PlantPreset::kBroadleaf, 3, options);
  const auto by_label = FacesByLabel(scene.mesh);
  EXPECT_FALSE(by_label.count(labels::kPot));
  EXPECT_FALSE(by_label.count(labels::kSoil));
  Eigen::Vector3f min, max;
  geometry::Bounds(scene.mesh, &min, &max);
  EXPECT_NEAR(min.z(), 0.0f, 0.002f);
  EXPECT_EQ(scene.mesh.Validate(), "");
}

TEST(PlantGenerator, PresetNamesParseAndUnknownNamesAreRejected) {
  for (PlantPreset preset : AllPresets()) EXPECT_EQ(ParsePreset(PresetName(preset)), preset);
  EXPECT_EQ(AllPresets().size(), 4u);
  try {
    ParsePreset("cactus");
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'cactus'"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("rosette, broadleaf, strap, bushy"),
              std::string::npos);
  }
}

TEST(PlantGenerator, BadOptionsAreRejected) {
  PlantOptions negative;
  negative.leaf_segments = -1;
  EXPECT_THROW(GeneratePlant(PlantPreset::kRosette, 1, negative), std::invalid_argument);
  PlantOptions zero_target;
  zero_target.target_triangles = 0;
  EXPECT_THROW(GeneratePlant(PlantPreset::kRosette, 1, zero_target), std::invalid_argument);
}

}  // namespace
}  // namespace avc::sim
