// The surfacer on the simulated plants: ~3000 points sampled on the leaves of each preset (the
// paper's merged density, 0.2 mm noise), clustered one cluster per leaf or by the paper's
// Algorithm 2, surfaced, and evaluated against the leaves' ground truth (core/eval). The
// figures are printed.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstring>

#include "bench/surface/leaf_connectivity.h"
#include "core/cluster/cluster_plant.h"
#include "core/eval/metrics.h"
#include "core/surface/surface_reconstruction.h"
#include "core/traits/plant_traits.h"
#include "sim/scene/plant.h"
#include "tests/core/surface/surface_test_points.h"

namespace avc::surface {
namespace {

constexpr int kPoints = 3000;
constexpr double kNoise = 0.0002;  // m per axis, as the Table 2 sets

struct Figures {
  double area_ratio = 0;
  double rmse = 0;
  int connected_leaves = 0;              // leaves in one piece
  double connected_fraction = 0;         // ... over the leaves
  double mostly_connected_fraction = 0;  // leaves with >= 95 % of their area in one piece
  double seconds = 0;
  SurfaceReport report;
};

// clustered: clusters from the paper's Algorithm 2 (cluster::ClusterPlant); else one cluster
// per leaf (its ground-truth label).
Figures Measure(sim::PlantPreset preset, uint32_t seed, bool clustered,
                const SurfaceOptions& options = {}) {
  const sim::Scene scene = sim::GeneratePlant(preset, seed);
  geometry::Mesh truth;
  ClusteredPoints points = test::SampleLeaves(scene.mesh, kPoints, kNoise, seed, &truth);
  if (clustered) {
    cluster::PointSet set;
    set.points = points.cloud.positions;
    set.normals = points.cloud.normals;
    points.clusters = cluster::ClusterPlant(set);
  }

  const auto start = std::chrono::steady_clock::now();
  const SurfaceResult result = ReconstructSurface(points, options);
  Figures figures;
  figures.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  figures.report = result.report;
  const eval::EvalResult eval = eval::EvaluateMesh(truth, result.mesh, eval::EvalOptions{});
  figures.area_ratio = eval.area_ratio.value_or(0.0);
  figures.rmse = eval.accuracy.rmse;
  const bench::LeafConnectivity leaves = bench::CountConnectedLeaves(truth, result.mesh);
  figures.connected_leaves = leaves.one_component;
  figures.connected_fraction = static_cast<double>(leaves.one_component) / leaves.leaves;
  figures.mostly_connected_fraction = static_cast<double>(leaves.mostly_one) / leaves.leaves;
  std::printf(
      "%-9s seed %u %s: area ratio %.3f, RMSE %.2f mm, leaves one component %d/%d (95 %% of area "
      "in one: %d), %.3f s "
      "(spacing %.2f mm, %zu clusters, %zu cells, %zu stitch faces, %zu components)\n",
      std::string(sim::PresetName(preset)).c_str(), seed,
      clustered ? "Algorithm 2 clusters" : "leaf clusters", figures.area_ratio, 1e3 * figures.rmse,
      leaves.one_component, leaves.leaves, leaves.mostly_one, figures.seconds,
      1e3 * result.report.thresholds.spacing, result.report.clusters, result.report.cells,
      result.report.stitching.faces, static_cast<size_t>(result.report.components));
  return figures;
}

class PlantSurfaceTest : public ::testing::TestWithParam<sim::PlantPreset> {};

// One cluster per leaf: the targets (area ratio 0.9-1.1; RMSE below CGAL's advancing
// front, 0.42-0.75 mm in `avc bench surface`) are met on every preset. Connectivity: the share of
// leaves with >= 95 % of their area in one piece (bench/surface/leaf_connectivity.h; 18/18, 11/11,
// 14/14 and 50/50 with seed 1; 0.83-0.89 on the rosette before ambiguous faces were settled).
TEST_P(PlantSurfaceTest, LeafClusters) {
  const Figures figures = Measure(GetParam(), 1, false);
  EXPECT_GE(figures.area_ratio, 0.9);
  EXPECT_LE(figures.area_ratio, 1.1);
  EXPECT_LT(figures.rmse, 0.0006);  // 0.26-0.48 mm measured; 0.64-0.90 without the refinement
  EXPECT_GE(figures.mostly_connected_fraction, 0.8);
}

// Clusters from the paper's Algorithm 2 (several per leaf, some spanning leaves at the rosette's
// centre). The area target holds on every preset. Connectivity is printed, not asserted: it
// follows the clustering (core/cluster, still changing) more than the surfacer; measured with
// seed 1: 16 of 18 rosette leaves, 11/11 broadleaf, 14/14 strap, 49/50 bushy leaves with >= 95 %
// of their area in one piece.
TEST_P(PlantSurfaceTest, AlgorithmTwoClusters) {
  const Figures figures = Measure(GetParam(), 1, true);
  EXPECT_GE(figures.area_ratio, 0.9);
  EXPECT_LE(figures.area_ratio, 1.1);
  EXPECT_LT(figures.rmse, 0.002);
}

INSTANTIATE_TEST_SUITE_P(Presets, PlantSurfaceTest, ::testing::ValuesIn(sim::AllPresets()),
                         [](const auto& param_info) {
                           return std::string(sim::PresetName(param_info.param));
                         });

// Phase 4 at the rosette's centre, where the leaf bases lie stacked a few millimetres apart:
// stitches that would pass over a third leaf's cell are refused, and the cells of one leaf are
// stitched across the wider gaps of its sparsely sampled arching tip (both the defaults,
// surface_options.h), also where Phase 3 cut the tip off its cell (cell_islands.h). Measured
// with seed 1: 17 of 18 leaves in one piece, 10 with neither rule. The optional link test
// between clusters keeps them apart as well.
TEST(PlantSurface, StitchesLeaveTheRosettesStackedLeafBasesApart) {
  SurfaceOptions neither;
  neither.stitch_clear_of_other_cells = false;
  neither.own_cluster_stitch_factor = 0;
  SurfaceOptions linked;
  linked.stitch_link_mean_slope = 0.1;
  const Figures before = Measure(sim::PlantPreset::kRosette, 1, false, neither);
  const Figures by_default = Measure(sim::PlantPreset::kRosette, 1, false);
  const Figures with_link = Measure(sim::PlantPreset::kRosette, 1, false, linked);
  EXPECT_GE(by_default.connected_leaves, 17);
  EXPECT_GE(by_default.connected_leaves, before.connected_leaves + 5);
  EXPECT_LT(by_default.rmse, 0.00046);
  EXPECT_GE(by_default.area_ratio, 0.95);
  EXPECT_GE(with_link.connected_leaves, 16);
  EXPECT_LT(with_link.rmse, 0.0004);
  EXPECT_GE(with_link.area_ratio, 0.9);
  std::printf(
      "rosette leaves in one piece: %d before, %d by default, %d linked; RMSE %.3f, %.3f mm\n",
      before.connected_leaves, by_default.connected_leaves, with_link.connected_leaves,
      1e3 * by_default.rmse, 1e3 * with_link.rmse);
}

// The traits of the surfaced leaves against the traits of the true leaves.
TEST(PlantSurface, TraitsMatchTheTruth) {
  const sim::Scene scene = sim::GeneratePlant(sim::PlantPreset::kBroadleaf, 2);
  geometry::Mesh truth;
  ClusteredPoints points = test::SampleLeaves(scene.mesh, kPoints, kNoise, 2, &truth);
  cluster::PointSet set;
  set.points = points.cloud.positions;
  set.normals = points.cloud.normals;
  points.clusters = cluster::ClusterPlant(set);
  const geometry::Mesh mesh = ReconstructSurface(points).mesh;
  traits::TraitOptions options;
  options.ground_z = 0.0;
  const traits::PlantTraits measured = traits::MeasureTraits(mesh, options);
  const traits::PlantTraits expected = traits::MeasureTraits(truth, options);
  EXPECT_NEAR(measured.height, expected.height, 0.003);
  EXPECT_NEAR(measured.width, expected.width, 0.02 * expected.width);
  EXPECT_NEAR(measured.total_area, expected.total_area, 0.1 * expected.total_area);
  EXPECT_NEAR(measured.hull_volume, expected.hull_volume, 0.1 * expected.hull_volume);
  EXPECT_GT(measured.clusters.size(), 5u);
}

TEST(PlantSurface, SameInputGivesTheSameBytes) {
  const sim::Scene scene = sim::GeneratePlant(sim::PlantPreset::kBushy, 4);
  geometry::Mesh truth;
  ClusteredPoints points = test::SampleLeaves(scene.mesh, kPoints, kNoise, 4, &truth);
  cluster::PointSet set;
  set.points = points.cloud.positions;
  set.normals = points.cloud.normals;
  points.clusters = cluster::ClusterPlant(set);
  const geometry::Mesh a = ReconstructSurface(points).mesh;
  const geometry::Mesh b = ReconstructSurface(points).mesh;
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.faces.size(), b.faces.size());
  EXPECT_EQ(0, std::memcmp(a.vertices.data(), b.vertices.data(),
                           a.vertices.size() * sizeof(Eigen::Vector3f)));
  EXPECT_EQ(0,
            std::memcmp(a.faces.data(), b.faces.data(), a.faces.size() * sizeof(Eigen::Vector3i)));
  EXPECT_EQ(a.face_labels, b.face_labels);
}

}  // namespace
}  // namespace avc::surface
