// Reading the real meshes in shared/data (CGAL, OpenCV, PhenoArch synthetic maize): counts
// checked against an independent count of the files, and exact round trips of real data.
// Skips when the shared data is absent.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/geometry/mesh_io.h"
#include "tests/support/test_support.h"

namespace avc::geometry {
namespace {

std::filesystem::path SharedData() { return avc::testing::SharedDataDir(); }

struct RealMesh {
  const char* path;  // under shared/data
  size_t vertices;
  size_t triangles;
  bool colored;
};

// Counted with an independent script over the files (polygons fanned; all are triangles).
constexpr RealMesh kRealMeshes[] = {
    {"meshes/cgal/ChineseDragon-10kv.off", 10000, 19994, false},
    {"meshes/cgal/armadillo.off", 26002, 52000, false},
    {"meshes/cgal/bunny00.off", 37706, 75408, false},
    {"meshes/cgal/cactus.off", 620, 1236, true},
    {"meshes/cgal/dino.off", 3916, 7828, true},
    {"meshes/cgal/elephant.off", 2775, 5558, false},
    {"meshes/cgal/kitten.off", 5210, 0, false},
    {"meshes/cgal/mushroom.off", 2337, 4608, false},
    {"meshes/cgal/sphere966.off", 926, 1848, false},
    {"meshes/opencv/bunny.ply", 1889, 3851, false},
    {"meshes/opencv/parasaurolophus_6700.ply", 6700, 9140, false},
    {"maize_phenoarch/examples_data/synthetic_plant_1/synthetic_plant.ply", 6005, 11922, false},
    {"maize_phenoarch/examples_data/synthetic_plant_2/synthetic_plant.ply", 1181, 2346, false},
};

TEST(MeshIoRealFiles, CountsMatchTheFiles) {
  for (const RealMesh& real : kRealMeshes) {
    const std::filesystem::path path = SharedData() / real.path;
    if (!std::filesystem::exists(path)) {
      GTEST_SKIP() << "shared data absent: " << path;
    }
    const Mesh mesh = ReadMesh(path);
    EXPECT_EQ(mesh.vertices.size(), real.vertices) << real.path;
    EXPECT_EQ(mesh.faces.size(), real.triangles) << real.path;
    EXPECT_EQ(mesh.colors.size(), real.colored ? real.vertices : 0u) << real.path;
    EXPECT_EQ(mesh.Validate(), "") << real.path;
  }
}

TEST(MeshIoRealFiles, KnownValuesAreReadExactly) {
  const std::filesystem::path maize =
      SharedData() / "maize_phenoarch/examples_data/synthetic_plant_1/synthetic_plant.ply";
  const std::filesystem::path cactus = SharedData() / "meshes/cgal/cactus.off";
  if (!std::filesystem::exists(maize) || !std::filesystem::exists(cactus)) {
    GTEST_SKIP() << "shared data absent under " << SharedData();
  }
  const Mesh plant = ReadMesh(maize);
  // First vertex line "0.614641 0.420826 -0.00174524"; the plant is 179.023 mm tall.
  EXPECT_EQ(plant.vertices[0], Eigen::Vector3f(0.614641f, 0.420826f, -0.00174524f));
  Eigen::Vector3f min;
  Eigen::Vector3f max;
  Bounds(plant, &min, &max);
  EXPECT_FLOAT_EQ(max.z(), 179.023f);
  EXPECT_FLOAT_EQ(min.x(), -61.8805f);

  const Mesh mesh = ReadMesh(cactus);
  // "0.0687881 0.0462836 -0.0243483 192 192 192 255"; last face "3 577 576 619".
  EXPECT_EQ(mesh.vertices[0], Eigen::Vector3f(0.0687881f, 0.0462836f, -0.0243483f));
  EXPECT_EQ(mesh.colors[0], (Eigen::Matrix<uint8_t, 3, 1>(192, 192, 192)));
  EXPECT_EQ(mesh.faces.back(), Eigen::Vector3i(577, 576, 619));
}

TEST(MeshIoRealFiles, RealMeshRoundTripsThroughBinaryPly) {
  const std::filesystem::path bunny = SharedData() / "meshes/cgal/bunny00.off";
  if (!std::filesystem::exists(bunny)) GTEST_SKIP() << "shared data absent: " << bunny;
  const Mesh mesh = ReadMesh(bunny);
  avc::testing::TempDir dir;
  WriteMeshPly(dir / "bunny.ply", mesh);
  const Mesh back = ReadMesh(dir / "bunny.ply");
  EXPECT_EQ(back.vertices, mesh.vertices);
  EXPECT_EQ(back.faces, mesh.faces);
}

}  // namespace
}  // namespace avc::geometry
