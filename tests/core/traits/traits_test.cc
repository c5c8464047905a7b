// Plant traits on meshes with known answers, and the traits.csv / JSON writer.

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "core/traits/convex_hull_volume.h"
#include "core/traits/curvature.h"
#include "core/traits/plant_traits.h"
#include "core/traits/traits_writer.h"

namespace avc::traits {
namespace {

// A w x d rectangle in the z = 0 plane split into n x n quads, facing +z, label per face.
geometry::Mesh Rectangle(double w, double d, int n, int32_t label) {
  geometry::Mesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      mesh.vertices.emplace_back(static_cast<float>(w * i / n), static_cast<float>(d * j / n),
                                 0.0f);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, e = c + 1;
      mesh.faces.emplace_back(a, b, e);
      mesh.faces.emplace_back(a, e, c);
    }
  }
  mesh.face_labels.assign(mesh.faces.size(), label);
  return mesh;
}

void Transform(geometry::Mesh& mesh, const Eigen::Affine3d& transform) {
  for (Eigen::Vector3f& v : mesh.vertices) v = (transform * v.cast<double>()).cast<float>();
}

// A UV sphere of radius r, outward faces.
geometry::Mesh Sphere(double r, int rings, int segments) {
  geometry::Mesh mesh;
  mesh.vertices.emplace_back(0.0f, 0.0f, static_cast<float>(r));
  for (int i = 1; i < rings; ++i) {
    const double theta = std::numbers::pi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / segments;
      mesh.vertices.emplace_back(static_cast<float>(r * std::sin(theta) * std::cos(phi)),
                                 static_cast<float>(r * std::sin(theta) * std::sin(phi)),
                                 static_cast<float>(r * std::cos(theta)));
    }
  }
  mesh.vertices.emplace_back(0.0f, 0.0f, static_cast<float>(-r));
  const int south = static_cast<int>(mesh.vertices.size()) - 1;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) {
    mesh.faces.emplace_back(0, ring(1, j), ring(1, j + 1));
    mesh.faces.emplace_back(south, ring(rings - 1, j + 1), ring(rings - 1, j));
    for (int i = 1; i + 1 < rings; ++i) {
      mesh.faces.emplace_back(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      mesh.faces.emplace_back(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
  }
  mesh.face_labels.assign(mesh.faces.size(), 0);
  return mesh;
}

TEST(PlantTraits, FlatLeafLyingDown) {
  const geometry::Mesh mesh = Rectangle(0.04, 0.03, 8, 5);
  const PlantTraits traits = MeasureTraits(mesh);
  EXPECT_NEAR(traits.total_area, 0.0012, 1e-9);
  EXPECT_NEAR(traits.height, 0.0, 1e-9);
  EXPECT_NEAR(traits.width, 0.05, 1e-6);  // the diagonal
  EXPECT_NEAR(traits.hull_volume, 0.0, 1e-12);
  ASSERT_EQ(traits.clusters.size(), 1u);
  EXPECT_EQ(traits.clusters[0].cluster, 5);
  EXPECT_NEAR(traits.clusters[0].inclination, 0.0, 1e-6);
  EXPECT_NEAR(traits.curvature.median, 0.0, 1e-6);
}

TEST(PlantTraits, TiltedLeafInclinationAndAzimuth) {
  // Tilted 30 degrees about the x axis: the normal leans towards -y (azimuth 270 degrees).
  geometry::Mesh mesh = Rectangle(0.02, 0.02, 4, 1);
  Transform(mesh,
            Eigen::Affine3d(Eigen::AngleAxisd(std::numbers::pi / 6, Eigen::Vector3d::UnitX())));
  const PlantTraits traits = MeasureTraits(mesh);
  ASSERT_EQ(traits.clusters.size(), 1u);
  EXPECT_NEAR(traits.clusters[0].inclination, std::numbers::pi / 6, 1e-5);
  EXPECT_NEAR(traits.clusters[0].azimuth, 1.5 * std::numbers::pi, 1e-5);
  EXPECT_NEAR(traits.height, 0.02 * std::sin(std::numbers::pi / 6), 1e-6);
}

TEST(PlantTraits, HeightFromGivenGroundAndGroupsOfClusters) {
  geometry::Mesh mesh = Rectangle(0.01, 0.01, 2, 1);
  geometry::Mesh other = Rectangle(0.01, 0.02, 2, 2);
  Transform(other, Eigen::Affine3d(Eigen::Translation3d(0.0, 0.0, 0.05)));
  mesh.Append(other);
  geometry::Mesh third = Rectangle(0.01, 0.01, 1, 3);
  Transform(third, Eigen::Affine3d(Eigen::Translation3d(0.1, 0.0, 0.02)));
  mesh.Append(third);
  TraitOptions options;
  options.ground_z = -0.01;
  options.group_of_cluster = {{1, 10}, {2, 10}};
  const PlantTraits traits = MeasureTraits(mesh, options);
  EXPECT_NEAR(traits.height, 0.06, 1e-6);
  EXPECT_DOUBLE_EQ(traits.height_base_z, -0.01);
  ASSERT_EQ(traits.groups.size(), 2u);
  EXPECT_EQ(traits.groups[0].group, 3);
  EXPECT_NEAR(traits.groups[0].area, 1e-4, 1e-9);
  EXPECT_EQ(traits.groups[1].group, 10);
  EXPECT_NEAR(traits.groups[1].area, 3e-4, 1e-9);
  EXPECT_EQ(traits.groups[1].clusters, (std::vector<int32_t>{1, 2}));
  EXPECT_NEAR(traits.width, std::hypot(0.11, 0.02), 1e-6);
  EXPECT_GT(traits.hull_volume, 0.0);
}

TEST(PlantTraits, SphereCurvatureAndHullVolume) {
  const double r = 0.05;
  const PlantTraits traits = MeasureTraits(Sphere(r, 40, 80));
  EXPECT_NEAR(traits.curvature.median, 1.0 / r, 0.02 / r);
  EXPECT_NEAR(traits.curvature.mean, 1.0 / r, 0.03 / r);
  EXPECT_NEAR(traits.hull_volume, 4.0 / 3.0 * std::numbers::pi * r * r * r, 0.01 * r * r * r * 4);
  EXPECT_NEAR(traits.total_area, 4.0 * std::numbers::pi * r * r, 0.01 * 4 * r * r);
  EXPECT_NEAR(traits.height, 2 * r, 1e-6);
}

TEST(ConvexHullVolume, CubeAndDegenerateSets) {
  std::vector<Eigen::Vector3f> cube;
  for (int k = 0; k < 8; ++k) {
    cube.emplace_back(0.1f * (k & 1), 0.1f * ((k >> 1) & 1), 0.1f * ((k >> 2) & 1));
  }
  cube.emplace_back(0.05f, 0.05f, 0.05f);  // inside
  EXPECT_NEAR(ConvexHullVolume(cube), 1e-3, 1e-9);
  EXPECT_EQ(ConvexHullVolume({}), 0.0);
  EXPECT_EQ(ConvexHullVolume({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}), 0.0);
  EXPECT_EQ(ConvexHullVolume({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}}), 0.0);
}

// CGAL lists the hull's faces in an order that depends on the process's memory layout; the
// volume must not (traits.csv differed in its last digits between two runs of one demo).
TEST(ConvexHullVolume, TheSameBitsWhateverTheCallHistoryAndPointOrder) {
  std::vector<Eigen::Vector3f> blob;
  uint32_t state = 12345;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24) - 0.5f;
  };
  for (int k = 0; k < 4000; ++k) blob.emplace_back(0.1f * next(), 0.07f * next(), 0.2f * next());
  const double first = ConvexHullVolume(blob);
  for (int repeat = 0; repeat < 4; ++repeat) {
    std::vector<Eigen::Vector3f> kept(blob.begin() + repeat, blob.end());  // other allocations
    EXPECT_EQ(ConvexHullVolume(blob), first) << "call " << repeat;
  }
  std::vector<Eigen::Vector3f> reversed(blob.rbegin(), blob.rend());
  EXPECT_EQ(ConvexHullVolume(reversed), first);
  EXPECT_GT(first, 0.5 * 0.1 * 0.07 * 0.2);  // most of the box
  EXPECT_LT(first, 0.1 * 0.07 * 0.2);
}

TEST(PlantTraits, EmptyAndBadMeshes) {
  const PlantTraits empty = MeasureTraits(geometry::Mesh{});
  EXPECT_EQ(empty.total_area, 0.0);
  EXPECT_TRUE(empty.clusters.empty());
  geometry::Mesh bad = Rectangle(0.01, 0.01, 1, 0);
  bad.faces[0][1] = 99;
  EXPECT_THROW(MeasureTraits(bad), std::invalid_argument);
  TraitOptions options;
  options.ground_z = std::nan("");
  EXPECT_THROW(MeasureTraits(Rectangle(0.01, 0.01, 1, 0), options), std::invalid_argument);
}

// The value of the CSV row starting with key, or NaN.
double CsvValue(const std::string& text, const std::string& key) {
  const size_t at = text.find("\n" + key);
  if (at == std::string::npos) return std::nan("");
  return std::stod(text.substr(at + 1 + key.size()));
}

TEST(TraitsWriter, CsvAndJsonCarryTheSameFigures) {
  geometry::Mesh mesh = Rectangle(0.02, 0.02, 4, 7);
  Transform(mesh,
            Eigen::Affine3d(Eigen::AngleAxisd(std::numbers::pi / 4, Eigen::Vector3d::UnitY())));
  const PlantTraits traits = MeasureTraits(mesh);
  std::ostringstream csv;
  WriteTraitsCsv(traits, csv);
  const std::string text = csv.str();
  EXPECT_EQ(text.rfind("scope,id,trait,value,unit\n", 0), 0u);
  EXPECT_NEAR(CsvValue(text, "plant,,total_area,"), 4e-4, 1e-10) << text;
  EXPECT_NEAR(CsvValue(text, "cluster,7,inclination,"), 45.0, 1e-4) << text;
  EXPECT_NEAR(CsvValue(text, "group,7,area,"), 4e-4, 1e-10) << text;
  const nlohmann::json json = TraitsToJson(traits);
  EXPECT_NEAR(json["total_area_m2"].get<double>(), 4e-4, 1e-10);
  // Without a ground the height is measured from the mesh's lowest point.
  EXPECT_NEAR(json["height_base_z_m"].get<double>(), traits.height_base_z, 1e-15);
  EXPECT_NEAR(CsvValue(text, "plant,,height_base_z,"), traits.height_base_z, 1e-15) << text;
  EXPECT_LT(traits.height_base_z, 0.0);
  EXPECT_NEAR(json["clusters"][0]["inclination_deg"].get<double>(), 45.0, 1e-4);
  EXPECT_NEAR(json["clusters"][0]["azimuth_deg"].get<double>(), 0.0, 1e-4);

  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("avc_traits_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  WriteTraitFiles(traits, dir.string());
  std::ifstream in(dir / "traits.csv");
  std::stringstream back;
  back << in.rdbuf();
  EXPECT_EQ(back.str(), text);
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(dir / "traits.json")), json);
  std::filesystem::remove_all(dir);
  EXPECT_THROW(WriteTraitFiles(traits, (dir / "missing" / "deeper").string()), std::runtime_error);
}

}  // namespace
}  // namespace avc::traits
