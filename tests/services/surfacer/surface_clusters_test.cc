// The surfacer library: clusters to a mesh with cluster ids and colours and the plant's traits,
// problems reported by name and never thrown, the files it writes, and the mesh message codec.

#include "services/surfacer/surface_clusters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>

#include "core/geometry/mesh_io.h"
#include "services/surfacer/plant_base.h"
#include "tests/support/test_support.h"
#include "tests/services/surfacer/two_leaf_clusters.h"

namespace avc::surfacer {
namespace {

TEST(SurfaceClusters, TwoLeavesBecomeAMeshWithClusterIdsColoursAndTraits) {
  const SurfacerResult result = SurfaceClusters(testing::TwoLeafClusters("plant-mvs-1"));
  ASSERT_EQ(result.problem, "");
  EXPECT_EQ(result.cloud_id, "plant-mvs-1");
  const geometry::Mesh& mesh = result.mesh;
  EXPECT_EQ(mesh.Validate(), "");
  ASSERT_EQ(mesh.face_labels.size(), mesh.faces.size());
  EXPECT_EQ(std::set<int32_t>(mesh.face_labels.begin(), mesh.face_labels.end()),
            (std::set<int32_t>{0, 1}));
  ASSERT_EQ(mesh.colors.size(), mesh.vertices.size());
  EXPECT_EQ(mesh.colors.front().x(), 40);
  // Evenly sampled discs: the surfacer's growth restores the outline (area within 5 %), and
  // two leaves 4 cm apart stay two pieces.
  EXPECT_NEAR(geometry::SurfaceArea(mesh), testing::TwoLeafArea(), 0.05 * testing::TwoLeafArea());
  EXPECT_EQ(result.report.components, 2);
  EXPECT_NEAR(result.traits.total_area, geometry::SurfaceArea(mesh), 1e-9);
  ASSERT_EQ(result.traits.clusters.size(), 2u);
  EXPECT_NEAR(result.traits.clusters[0].inclination, 0.0, 0.05);  // facing up
}

TEST(PlantBase, IsTheBottomOfTheProxysLowestVoxel) {
  mvs::MvsBounds proxy;
  EXPECT_FALSE(PlantBaseZ(proxy).has_value());
  proxy.voxel_size = 0.002;
  proxy.occupied_centres = {{0.01f, 0.0f, 0.081f}, {0.0f, 0.02f, 0.051f}, {0.0f, 0.0f, 0.12f}};
  ASSERT_TRUE(PlantBaseZ(proxy).has_value());
  EXPECT_NEAR(*PlantBaseZ(proxy), 0.050, 1e-6);
}

TEST(SurfaceClusters, ProblemsAreReportedByNameNotThrown) {
  messages::ClustersContent refused;
  refused.cloud_id = "c1";
  refused.problem = "no plant proxy arrived";
  SurfacerResult result = SurfaceClusters(refused);
  EXPECT_NE(result.problem.find("'c1'"), std::string::npos) << result.problem;
  EXPECT_NE(result.problem.find("no plant proxy arrived"), std::string::npos) << result.problem;
  EXPECT_TRUE(result.mesh.faces.empty());

  messages::ClustersContent short_ids = testing::TwoLeafClusters("c2");
  short_ids.clusters.pop_back();
  result = SurfaceClusters(short_ids);
  EXPECT_NE(result.problem.find("'c2'"), std::string::npos) << result.problem;
  EXPECT_NE(result.problem.find("cluster"), std::string::npos) << result.problem;

  messages::ClustersContent outliers = testing::TwoLeafClusters("c3");
  for (int32_t& id : outliers.clusters) id = cluster::kUnassigned;
  result = SurfaceClusters(outliers);
  EXPECT_NE(result.problem.find("no surface could be made"), std::string::npos) << result.problem;

  // A NaN point is left out with a warning; the rest is surfaced.
  messages::ClustersContent nan = testing::TwoLeafClusters("c4");
  nan.merged.cloud.positions[10].x() = std::numeric_limits<float>::quiet_NaN();
  result = SurfaceClusters(nan);
  EXPECT_EQ(result.problem, "");
  EXPECT_FALSE(result.report.warnings.empty());

  SurfacerOptions bad;
  bad.surface.alpha_factor = -1;
  result = SurfaceClusters(testing::TwoLeafClusters("c5"), bad);
  EXPECT_NE(result.problem.find("alpha"), std::string::npos) << result.problem;
}

TEST(SurfaceClusters, WritesTheMeshAndTraitFiles) {
  ::avc::testing::TempDir dir("avc-surfacer-files");
  const SurfacerResult result = SurfaceClusters(testing::TwoLeafClusters("plant-mvs-1"));
  WriteSurfacerFiles(result, dir / "out");
  const geometry::Mesh read = geometry::ReadMesh(dir / "out" / "mesh.ply");
  EXPECT_EQ(read.vertices, result.mesh.vertices);
  EXPECT_EQ(read.face_labels, result.mesh.face_labels);
  EXPECT_EQ(read.colors, result.mesh.colors);
  const std::string csv = ::avc::testing::ReadFile(dir / "out" / "traits.csv");
  EXPECT_NE(csv.find("total_area"), std::string::npos) << csv;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "traits.json"));
}

}  // namespace
}  // namespace avc::surfacer
