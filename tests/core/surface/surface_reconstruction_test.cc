// The surfacer end to end on analytic sheets with known area, on bad input, and for
// determinism.

#include "core/surface/surface_reconstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/cluster/point_set.h"
#include "core/surface/mesh_topology.h"
#include "tests/core/surface/surface_test_points.h"

namespace avc::surface {
namespace {

constexpr double kRadius = 0.03;  // m
const double kDiscArea = std::numbers::pi * kRadius * kRadius;

bool AnyWarningMentions(const SurfaceReport& report, const std::string& text) {
  for (const std::string& warning : report.warnings) {
    if (warning.find(text) != std::string::npos) return true;
  }
  return false;
}

// Closed boundary loops that are not a piece's outer boundary.
size_t CountHoles(const geometry::Mesh& mesh) {
  const std::vector<BoundaryLoop> loops = BoundaryLoops(mesh);
  const std::vector<bool> outer = OuterLoops(mesh, loops);
  size_t holes = 0;
  for (size_t i = 0; i < loops.size(); ++i) holes += outer[i] ? 0 : 1;
  return holes;
}

TEST(SurfaceReconstruction, EvenDiscIsOneCellWithTheDiscArea) {
  const SurfaceResult result = ReconstructSurface(test::SpiralDisc(kRadius, 3000));
  EXPECT_TRUE(result.mesh.Validate().empty()) << result.mesh.Validate();
  EXPECT_EQ(result.report.cells, 1u);
  EXPECT_EQ(result.report.components, 1);
  EXPECT_EQ(CountHoles(result.mesh), 0u);
  EXPECT_NEAR(geometry::SurfaceArea(result.mesh) / kDiscArea, 1.0, 0.02);
  EXPECT_TRUE(result.report.warnings.empty());
  // Flat input stays flat and faces +z like its normals.
  for (const Eigen::Vector3f& v : result.mesh.vertices) EXPECT_NEAR(v.z(), 0.0f, 1e-6f);
  for (const Eigen::Vector3i& t : result.mesh.faces) {
    const Eigen::Vector3f n = (result.mesh.vertices[t[1]] - result.mesh.vertices[t[0]])
                                  .cross(result.mesh.vertices[t[2]] - result.mesh.vertices[t[0]]);
    EXPECT_GT(n.z(), 0.0f);
  }
  ASSERT_EQ(result.mesh.face_labels.size(), result.mesh.faces.size());
  for (int32_t label : result.mesh.face_labels) EXPECT_EQ(label, 0);
}

TEST(SurfaceReconstruction, RandomDiscHasTheDiscArea) {
  const SurfaceResult result = ReconstructSurface(test::RandomDisc(kRadius, 3000, 3));
  EXPECT_EQ(result.report.components, 1);
  // Random samples leave the odd gap wider than the hole bound (one here).
  EXPECT_LE(CountHoles(result.mesh), 1u);
  EXPECT_NEAR(geometry::SurfaceArea(result.mesh) / kDiscArea, 1.0, 0.03);
}

TEST(SurfaceReconstruction, WithoutGrowthTheOutlineLiesInsideTheDisc) {
  SurfaceOptions options;
  options.grow_boundary = false;
  const SurfaceResult result = ReconstructSurface(test::SpiralDisc(kRadius, 3000), options);
  const double ratio = geometry::SurfaceArea(result.mesh) / kDiscArea;
  EXPECT_LT(ratio, 0.99);
  EXPECT_GT(ratio, 0.95);
}

TEST(SurfaceReconstruction, CylindricalSheetKeepsItsArea) {
  const double r = 0.04, angle = std::numbers::pi / 2, height = 0.06;
  const ClusteredPoints points = test::CylinderSheet(r, angle, height, 3000, 5);
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_EQ(result.report.components, 1);
  EXPECT_NEAR(geometry::SurfaceArea(result.mesh) / (r * angle * height), 1.0, 0.04);
  // The surface stays on the cylinder (smoothing must not flatten it).
  double worst = 0.0;
  for (const Eigen::Vector3f& v : result.mesh.vertices) {
    worst = std::max(worst, std::abs(std::hypot(v.x(), v.z()) - r));
  }
  EXPECT_LT(worst, 0.001);
}

// The fitted-surface refinement subdivides every cell and moves every vertex onto its fit.
TEST(SurfaceReconstruction, RefinementSubdividesAndProjectsEveryVertex) {
  const ClusteredPoints points = test::CylinderSheet(0.04, std::numbers::pi / 2, 0.06, 3000, 5);
  SurfaceOptions flat;
  flat.refine = false;
  const SurfaceResult refined = ReconstructSurface(points);
  const SurfaceResult unrefined = ReconstructSurface(points, flat);
  // Kept: vertices of faces Phase 3 removed, far from every sample (dropped at the end).
  EXPECT_LT(refined.report.refinement.vertices_kept,
            0.01 * refined.report.refinement.vertices_projected);
  EXPECT_EQ(unrefined.report.refinement.vertices_projected, 0u);
  EXPECT_GT(refined.report.refinement.vertices_added, unrefined.mesh.vertices.size());
  EXPECT_GT(refined.mesh.faces.size(), 3 * unrefined.mesh.faces.size());
  EXPECT_NEAR(geometry::SurfaceArea(refined.mesh), geometry::SurfaceArea(unrefined.mesh),
              0.01 * geometry::SurfaceArea(unrefined.mesh));
}

TEST(SurfaceReconstruction, TwoTouchingClustersBecomeOneComponent) {
  ClusteredPoints points = test::SpiralDisc(kRadius, 3000);
  for (size_t i = 0; i < points.clusters.size(); ++i) {
    points.clusters[i] = points.cloud.positions[i].x() < 0.0f ? 0 : 1;
  }
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_EQ(result.report.cells, 2u);
  EXPECT_GT(result.report.stitching.faces, 0u);
  EXPECT_EQ(result.report.components, 1);
  EXPECT_NEAR(geometry::SurfaceArea(result.mesh) / kDiscArea, 1.0, 0.03);
  // Both clusters keep their faces' labels.
  size_t left = 0, right = 0;
  for (int32_t label : result.mesh.face_labels) (label == 0 ? left : right)++;
  EXPECT_GT(left, 1000u);
  EXPECT_GT(right, 1000u);
}

TEST(SurfaceReconstruction, FoldedClustersMeetingAtAnAngleAreJoined) {
  // Two half discs hinged along the y axis at 30 degrees to each other.
  ClusteredPoints points = test::SpiralDisc(kRadius, 3000);
  const double tilt = std::numbers::pi / 6;
  for (size_t i = 0; i < points.clusters.size(); ++i) {
    Eigen::Vector3f& p = points.cloud.positions[i];
    if (p.x() < 0.0f) continue;
    points.clusters[i] = 1;
    const float x = p.x();
    p = Eigen::Vector3f(x * static_cast<float>(std::cos(tilt)), p.y(),
                        x * static_cast<float>(std::sin(tilt)));
    points.cloud.normals[i] = Eigen::Vector3f(static_cast<float>(-std::sin(tilt)), 0.0f,
                                              static_cast<float>(std::cos(tilt)));
  }
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_EQ(result.report.components, 1);
  EXPECT_NEAR(geometry::SurfaceArea(result.mesh) / kDiscArea, 1.0, 0.03);
}

TEST(SurfaceReconstruction, SeparateSheetsStayApart) {
  // Two discs 10 cm apart: nothing to stitch.
  ClusteredPoints points = test::SpiralDisc(kRadius, 1500);
  const ClusteredPoints other = test::SpiralDisc(kRadius, 1500);
  for (size_t i = 0; i < other.cloud.size(); ++i) {
    test::AddPoint(points, other.cloud.positions[i].cast<double>() + Eigen::Vector3d(0.1, 0, 0),
                   Eigen::Vector3d::UnitZ(), 1);
  }
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_EQ(result.report.components, 2);
  EXPECT_EQ(result.report.stitching.faces, 0u);
}

TEST(SurfaceReconstruction, SameInputGivesTheSameBytes) {
  ClusteredPoints points = test::RandomDisc(kRadius, 2000, 9);
  for (size_t i = 0; i < points.clusters.size(); ++i) {
    points.clusters[i] = points.cloud.positions[i].y() > 0.01f ? 1 : 0;
  }
  const SurfaceResult a = ReconstructSurface(points);
  const SurfaceResult b = ReconstructSurface(points);
  ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
  ASSERT_EQ(a.mesh.faces.size(), b.mesh.faces.size());
  for (size_t i = 0; i < a.mesh.vertices.size(); ++i) {
    ASSERT_EQ(0,
              std::memcmp(a.mesh.vertices[i].data(), b.mesh.vertices[i].data(), sizeof(float) * 3));
  }
  for (size_t f = 0; f < a.mesh.faces.size(); ++f) ASSERT_EQ(a.mesh.faces[f], b.mesh.faces[f]);
  EXPECT_EQ(a.mesh.face_labels, b.mesh.face_labels);
}

TEST(SurfaceReconstruction, ColoursFollowThePoints) {
  ClusteredPoints points = test::SpiralDisc(kRadius, 500);
  points.cloud.colors.assign(points.cloud.size(), Eigen::Matrix<uint8_t, 3, 1>(10, 200, 30));
  const SurfaceResult result = ReconstructSurface(points);
  ASSERT_EQ(result.mesh.colors.size(), result.mesh.vertices.size());
  for (const auto& colour : result.mesh.colors) {
    EXPECT_EQ(colour, (Eigen::Matrix<uint8_t, 3, 1>(10, 200, 30)));
  }
}

TEST(SurfaceReconstruction, WorksWithoutNormals) {
  ClusteredPoints points = test::CylinderSheet(0.04, std::numbers::pi / 2, 0.06, 2000, 8);
  points.cloud.normals.clear();
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_EQ(result.report.components, 1);
  EXPECT_NEAR(geometry::SurfaceArea(result.mesh) / (0.04 * std::numbers::pi / 2 * 0.06), 1.0, 0.04);
}

TEST(SurfaceReconstruction, UnassignedPointsAreIgnored) {
  ClusteredPoints points = test::SpiralDisc(kRadius, 2000);
  test::AddPoint(points, {0.0, 0.0, 0.05}, Eigen::Vector3d::UnitZ(), cluster::kUnassigned);
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_EQ(result.report.used_points, 2000u);
  Eigen::Vector3f lo, hi;
  geometry::Bounds(result.mesh, &lo, &hi);
  EXPECT_LT(hi.z(), 1e-6f);
}

TEST(SurfaceReconstructionInput, CollinearClusterIsLeftOutWithAWarning) {
  ClusteredPoints points = test::SpiralDisc(kRadius, 1000);
  for (int i = 0; i < 20; ++i) {
    test::AddPoint(points, {0.1 + 0.001 * i, 0.0, 0.0}, Eigen::Vector3d::UnitZ(), 7);
  }
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_TRUE(AnyWarningMentions(result.report, "cluster 7")) << result.report.warnings.size();
  EXPECT_TRUE(AnyWarningMentions(result.report, "collinear"));
  EXPECT_EQ(result.report.cells, 1u);  // the disc is still surfaced
  EXPECT_EQ(result.report.components, 1);
}

TEST(SurfaceReconstructionInput, CoincidentClusterIsLeftOutWithAWarning) {
  ClusteredPoints points = test::SpiralDisc(kRadius, 1000);
  for (int i = 0; i < 10; ++i) test::AddPoint(points, {0.2, 0.1, 0.0}, Eigen::Vector3d::UnitZ(), 4);
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_TRUE(AnyWarningMentions(result.report, "cluster 4 (10 points): all points coincide"));
  EXPECT_EQ(result.report.components, 1);
}

TEST(SurfaceReconstructionInput, ClusterOfTwoPointsIsLeftOutWithAWarning) {
  ClusteredPoints points = test::SpiralDisc(kRadius, 1000);
  test::AddPoint(points, {0.2, 0.0, 0.0}, Eigen::Vector3d::UnitZ(), 3);
  test::AddPoint(points, {0.2, 0.001, 0.0}, Eigen::Vector3d::UnitZ(), 3);
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_TRUE(AnyWarningMentions(result.report, "cluster 3 (2 points): fewer than 3 points"));
  EXPECT_EQ(result.report.cells, 1u);
}

TEST(SurfaceReconstructionInput, FewerThanThreePointsGiveAnEmptyMeshAndAWarning) {
  ClusteredPoints points;
  test::AddPoint(points, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 0);
  test::AddPoint(points, {0.001, 0, 0}, Eigen::Vector3d::UnitZ(), 0);
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_TRUE(result.mesh.faces.empty());
  EXPECT_FALSE(result.report.warnings.empty());
  EXPECT_TRUE(AnyWarningMentions(result.report, "spacing"));

  const SurfaceResult none = ReconstructSurface(ClusteredPoints{});
  EXPECT_TRUE(none.mesh.faces.empty());
  EXPECT_FALSE(none.report.warnings.empty());
}

TEST(SurfaceReconstructionInput, NonFinitePointsAreLeftOutWithAWarning) {
  ClusteredPoints points = test::SpiralDisc(kRadius, 2000);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  points.cloud.positions[17] = Eigen::Vector3f(nan, 0.0f, 0.0f);
  points.cloud.normals[30] = Eigen::Vector3f(0.0f, nan, 1.0f);
  const SurfaceResult result = ReconstructSurface(points);
  EXPECT_TRUE(AnyWarningMentions(result.report, "2 point(s) with a non-finite position or normal"));
  EXPECT_TRUE(AnyWarningMentions(result.report, "first: point 17"));
  EXPECT_EQ(result.report.used_points, 1998u);
  EXPECT_TRUE(result.mesh.Validate().empty());
  EXPECT_NEAR(geometry::SurfaceArea(result.mesh) / kDiscArea, 1.0, 0.02);
}

TEST(SurfaceReconstructionInput, InconsistentInputIsRefusedNamingTheProblem) {
  ClusteredPoints points = test::SpiralDisc(kRadius, 100);
  points.clusters.pop_back();
  try {
    ReconstructSurface(points);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("99 cluster ids for 100 points"), std::string::npos)
        << error.what();
  }
  points = test::SpiralDisc(kRadius, 100);
  points.clusters[5] = -2;
  EXPECT_THROW(ReconstructSurface(points), std::invalid_argument);
  points = test::SpiralDisc(kRadius, 100);
  points.cloud.normals.pop_back();
  EXPECT_THROW(ReconstructSurface(points), std::invalid_argument);
}

TEST(SurfaceReconstructionInput, InvalidOptionsAreRefusedNamingTheField) {
  SurfaceOptions options;
  options.alpha_factor = -1.0;
  try {
    ReconstructSurface(test::SpiralDisc(kRadius, 100), options);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("alpha_factor"), std::string::npos);
  }
  options = SurfaceOptions{};
  options.cell_smoothing.mu = 0.2;
  EXPECT_NE(options.Validate().find("cell_smoothing.mu"), std::string::npos);
  options = SurfaceOptions{};
  options.stitch_link_mean_slope = std::nan("");
  EXPECT_NE(options.Validate().find("stitch_link_mean_slope"), std::string::npos);
  options = SurfaceOptions{};
  options.own_cluster_stitch_factor = std::numeric_limits<double>::infinity();
  EXPECT_NE(options.Validate().find("own_cluster_stitch_factor"), std::string::npos);
  EXPECT_EQ(SurfaceOptions{}.Validate(), "");
}

TEST(SurfaceReconstructionInput, GivenSpacingOverridesTheMeasuredOne) {
  SurfaceOptions options;
  options.spacing = 0.002;
  const SurfaceResult result = ReconstructSurface(test::SpiralDisc(kRadius, 1000), options);
  EXPECT_DOUBLE_EQ(result.report.thresholds.spacing, 0.002);
  EXPECT_DOUBLE_EQ(result.report.thresholds.alpha, 0.008);
  // One cluster's cells are stitched across 5.25 spacings, any two across 3.5; 0 asks for the
  // same distance.
  EXPECT_DOUBLE_EQ(result.report.thresholds.stitch_distance, 0.007);
  EXPECT_DOUBLE_EQ(result.report.thresholds.own_cluster_stitch_distance, 0.0105);
  options.own_cluster_stitch_factor = 0.0;
  EXPECT_DOUBLE_EQ(ResolveThresholds(options, 0.002, 0.0).own_cluster_stitch_distance, 0.007);
}

}  // namespace
}  // namespace avc::surface
