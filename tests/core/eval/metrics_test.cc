// Accuracy, completeness, scores, area ratio and the per-organ breakdown on cases with known
// answers: an offset plane, a half-covered sphere, a mesh against itself, two labelled sheets.

#include "core/eval/metrics.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "core/eval/report_json.h"
#include "tests/core/eval/test_scenes.h"

namespace avc::eval {
namespace {

using test::Grid;
using test::Rectangle;
using test::Sphere;

constexpr double kOffset = 0.003;

EvalOptions Options(double samples_per_m2 = 1e6) {
  EvalOptions options;
  options.thresholds = {0.001, 0.002, 0.005, 0.01};
  options.samples_per_m2 = samples_per_m2;
  options.seed = 7;
  return options;
}

void ExpectRelative(double actual, double expected, double tolerance = 1e-6) {
  EXPECT_NEAR(actual, expected, tolerance * std::abs(expected)) << "expected " << expected;
}

TEST(Metrics, PlaneOffsetCloudGivesTheOffset) {
  const geometry::Mesh gt = Rectangle(0, 0.1, 0, 0.1, 0, 4);
  // 1 mm grid, 3 mm above: every point is 3 mm from the plane, every GT sample within
  // sqrt(3^2 + 0.71^2) mm of a point.
  const geometry::PointCloud cloud = Grid(0, 0.1, 0, 0.1, kOffset, 0.001);
  const EvalResult result = EvaluatePointCloud(gt, cloud, Options());

  const double d = static_cast<float>(kOffset);  // what the float cloud holds
  EXPECT_EQ(result.accuracy.count, cloud.size());
  ExpectRelative(result.accuracy.rmse, d);
  ExpectRelative(result.accuracy.mean, d);
  ExpectRelative(result.accuracy.median, d);
  ExpectRelative(result.accuracy.p90, d);
  ExpectRelative(result.accuracy.max, d);
  EXPECT_GE(result.completeness.mean, d);
  EXPECT_LE(result.completeness.max, std::hypot(d, 0.0005 * std::sqrt(2.0)) + 1e-9);
  ASSERT_EQ(result.scores.size(), 4u);
  for (const ThresholdScore& score : result.scores) {
    const double expected = score.threshold > d ? 1.0 : 0.0;
    EXPECT_EQ(score.precision, expected) << "threshold " << score.threshold;
    EXPECT_EQ(score.recall, expected) << "threshold " << score.threshold;
    EXPECT_EQ(score.fscore, expected) << "threshold " << score.threshold;
  }
  EXPECT_FALSE(result.reconstruction_is_mesh);
  EXPECT_FALSE(result.area_ratio.has_value());
  EXPECT_NEAR(result.gt_area, 0.01, 1e-9);
  // 1e6 per m^2 on 0.01 m^2: about 10000 samples (per-face rounding keeps it within a few).
  EXPECT_NEAR(static_cast<double>(result.gt_samples.size()), 10000.0, 10.0);
  EXPECT_FALSE(result.gt_closed);
  EXPECT_EQ(result.gt_boundary_edges, 16u);
}

TEST(Metrics, PlaneOffsetMeshGivesTheOffsetAndAreaRatioOne) {
  const geometry::Mesh gt = Rectangle(0, 0.1, 0, 0.1, 0, 2);
  const geometry::Mesh reconstruction = Rectangle(0, 0.1, 0, 0.1, kOffset, 3);
  const EvalResult result = EvaluateMesh(gt, reconstruction, Options(2e5));
  const double d = static_cast<float>(kOffset);
  ExpectRelative(result.accuracy.rmse, d);
  ExpectRelative(result.accuracy.mean, d);
  // Mesh to mesh, the GT → reconstruction distance is exactly the offset too.
  ExpectRelative(result.completeness.mean, d);
  ExpectRelative(result.completeness.max, d);
  for (const ThresholdScore& score : result.scores) {
    EXPECT_EQ(score.recall, score.threshold > d ? 1.0 : 0.0) << score.threshold;
    EXPECT_EQ(score.precision, score.threshold > d ? 1.0 : 0.0) << score.threshold;
  }
  ASSERT_TRUE(result.area_ratio.has_value());
  EXPECT_NEAR(*result.area_ratio, 1.0, 1e-9);
  EXPECT_TRUE(result.reconstruction_is_mesh);
  EXPECT_NEAR(static_cast<double>(result.reconstruction_points), 2000.0, 10.0);
}

TEST(Metrics, MeshAgainstItselfIsPerfect) {
  const geometry::Mesh sphere = Sphere(0.05, 3);
  const EvalResult result = EvaluateMesh(sphere, sphere, Options(2e5));
  ASSERT_TRUE(result.area_ratio.has_value());
  EXPECT_DOUBLE_EQ(*result.area_ratio, 1.0);
  EXPECT_LT(result.accuracy.max, 1e-9);
  EXPECT_LT(result.completeness.max, 1e-9);
  for (const ThresholdScore& score : result.scores) EXPECT_EQ(score.fscore, 1.0);
  // A closed sphere has no boundary, and the note says what that means for areas.
  EXPECT_TRUE(result.gt_closed);
  EXPECT_NE(result.area_note.find("twice"), std::string::npos);
}

TEST(Metrics, HalfCoveredSphereIsHalfComplete) {
  const double radius = 0.05;
  const geometry::Mesh sphere = Sphere(radius, 4);
  // The reconstruction: dense points (about 0.5 mm apart) on the upper hemisphere only.
  const SurfaceSamples dense = SampleSurface(sphere, 4e6, 99);
  geometry::PointCloud upper;
  for (const Eigen::Vector3d& p : dense.points) {
    if (p.z() > 0) upper.positions.push_back(p.cast<float>());
  }
  EvalOptions options = Options();
  options.thresholds = {0.0005, 0.001};
  const EvalResult result = EvaluatePointCloud(sphere, upper, options);
  // Recall at τ covers the hemisphere plus a band of height ≈ τ: 0.5 + τ / (2 r) = 0.51 at 1 mm.
  EXPECT_NEAR(result.scores[1].recall, 0.5 + 0.001 / (2 * radius), 0.02);
  EXPECT_NEAR(result.scores[1].recall, 0.5, 0.02);
  EXPECT_EQ(result.scores[0].precision, 1.0);
  EXPECT_EQ(result.scores[1].precision, 1.0);
  EXPECT_LT(result.accuracy.max, 1e-6);  // float rounding of points on the surface
  EXPECT_TRUE(result.organs.empty());    // no face labels
}

TEST(Metrics, PerOrganBreakdownOnTwoLabelledSheets) {
  using geometry::labels::kLeafBase;
  geometry::Mesh gt = Rectangle(0, 0.1, 0, 0.1, 0, 2, kLeafBase);
  gt.Append(Rectangle(0.1, 0.2, 0, 0.1, 0, 2, kLeafBase + 1));
  // Leaf 0 reconstructed 1 mm off, leaf 1 4 mm off; the grids stop half a step from the seam.
  geometry::PointCloud cloud = Grid(0, 0.1, 0, 0.1, 0.001, 0.001);
  const geometry::PointCloud far = Grid(0.1, 0.2, 0, 0.1, 0.004, 0.001);
  cloud.positions.insert(cloud.positions.end(), far.positions.begin(), far.positions.end());
  const EvalResult result = EvaluatePointCloud(gt, cloud, Options(2e5));

  ASSERT_EQ(result.organs.size(), 2u);
  const OrganEval& near_leaf = result.organs[0];
  const OrganEval& far_leaf = result.organs[1];
  EXPECT_EQ(near_leaf.label, kLeafBase);
  EXPECT_EQ(near_leaf.name, "leaf 0");
  EXPECT_EQ(far_leaf.name, "leaf 1");
  EXPECT_NEAR(near_leaf.gt_area, 0.01, 1e-9);
  EXPECT_NEAR(far_leaf.gt_area, 0.01, 1e-9);
  EXPECT_EQ(near_leaf.accuracy.count, 10000u);
  EXPECT_EQ(far_leaf.accuracy.count, 10000u);
  ExpectRelative(near_leaf.accuracy.mean, static_cast<float>(0.001));
  ExpectRelative(far_leaf.accuracy.mean, static_cast<float>(0.004));
  EXPECT_EQ(near_leaf.completeness.count + far_leaf.completeness.count, result.gt_samples.size());
  // Thresholds 1, 2, 5, 10 mm: leaf 0 is complete from 2 mm, leaf 1 from 5 mm.
  EXPECT_EQ(near_leaf.scores[0].recall, 0.0);
  EXPECT_EQ(near_leaf.scores[1].recall, 1.0);
  // Leaf 1 samples within sqrt(2^2 - 1^2) = 1.7 mm of the seam are within 2 mm of leaf 0's points.
  EXPECT_NEAR(far_leaf.scores[1].recall, 0.0173, 0.01);
  EXPECT_EQ(far_leaf.scores[2].recall, 1.0);
  EXPECT_EQ(far_leaf.scores[1].precision, 0.0);
  EXPECT_EQ(far_leaf.scores[2].precision, 1.0);
  // Overall: half the points are within 2 mm.
  EXPECT_DOUBLE_EQ(result.scores[1].precision, 0.5);
  EXPECT_NEAR(result.scores[1].recall, 0.5, 0.02);
}

TEST(Metrics, ReconstructedAreaIsSplitByNearestOrgan) {
  using geometry::labels::kLeafBase;
  geometry::Mesh gt = Rectangle(0, 0.1, 0, 0.1, 0, 2, kLeafBase);
  gt.Append(Rectangle(0.1, 0.2, 0, 0.1, 0, 2, kLeafBase + 1));
  // Reconstruct leaf 0 fully and a quarter of leaf 1.
  geometry::Mesh reconstruction = Rectangle(0, 0.1, 0, 0.1, 0.0005, 2);
  reconstruction.Append(Rectangle(0.125, 0.175, 0.025, 0.075, 0.0005, 2));
  const EvalResult result = EvaluateMesh(gt, reconstruction, Options(1e6));
  ASSERT_TRUE(result.area_ratio.has_value());
  EXPECT_NEAR(*result.area_ratio, 0.0125 / 0.02, 1e-7);  // float vertices
  ASSERT_EQ(result.organs.size(), 2u);
  EXPECT_NEAR(*result.organs[0].reconstructed_area, 0.01, 0.0003);
  EXPECT_NEAR(*result.organs[1].reconstructed_area, 0.0025, 0.0003);
  // Recall at 1 mm on leaf 1: the quarter grown by sqrt(1^2 - 0.5^2) = 0.87 mm (rounded
  // corners), plus a 0.87 mm strip along the seam reached from leaf 0: 0.268 + 0.009.
  EXPECT_NEAR(result.organs[1].scores[0].recall, 0.276, 0.015);
}

TEST(Metrics, SameSeedGivesIdenticalJsonWhateverTheThreadCount) {
  const geometry::Mesh gt = Sphere(0.05, 3);
  const geometry::Mesh reconstruction = Sphere(0.051, 2);
  const std::string parallel = ToJson(EvaluateMesh(gt, reconstruction, Options(3e5))).dump();
  const std::string again = ToJson(EvaluateMesh(gt, reconstruction, Options(3e5))).dump();
  std::string serial;
  {
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    serial = ToJson(EvaluateMesh(gt, reconstruction, Options(3e5))).dump();
  }
  EXPECT_EQ(parallel, again);
  EXPECT_EQ(parallel, serial);
  EvalOptions other_seed = Options(3e5);
  other_seed.seed = 8;
  EXPECT_NE(parallel, ToJson(EvaluateMesh(gt, reconstruction, other_seed)).dump());
}

// Runs f, expecting std::invalid_argument whose message contains `needle`.
template <class F>
void ExpectInvalid(F f, const std::string& needle) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning '" << needle << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(Metrics, BadInputGivesClearErrors) {
  const geometry::Mesh gt = Rectangle(0, 0.1, 0, 0.1, 0);
  const geometry::PointCloud cloud = Grid(0, 0.1, 0, 0.1, 0, 0.01);

  ExpectInvalid([&] { EvaluatePointCloud(geometry::Mesh{}, cloud, Options()); },
                "ground truth mesh: no surface");
  geometry::Mesh broken = gt;
  broken.faces[1][2] = 17;
  ExpectInvalid([&] { EvaluatePointCloud(broken, cloud, Options()); },
                "ground truth mesh: face 1 refers to vertex 17");
  geometry::PointCloud nan_cloud = cloud;
  nan_cloud.positions[2].y() = std::nanf("");
  ExpectInvalid([&] { EvaluatePointCloud(gt, nan_cloud, Options()); },
                "reconstruction point cloud: point 2 is not finite");
  ExpectInvalid([&] { EvaluatePointCloud(gt, geometry::PointCloud{}, Options()); }, "no points");
  ExpectInvalid([&] { EvaluateMesh(gt, geometry::Mesh{}, Options()); },
                "reconstruction mesh: no surface");
  EvalOptions bad_threshold = Options();
  bad_threshold.thresholds = {0.001, -0.002};
  ExpectInvalid([&] { EvaluatePointCloud(gt, cloud, bad_threshold); }, "threshold -0.002");
  EvalOptions bad_density = Options();
  bad_density.samples_per_m2 = 0;
  ExpectInvalid([&] { EvaluatePointCloud(gt, cloud, bad_density); }, "samples per m^2 0");
  // A 100 mm plant read as 100 m: the sample budget names the likely cause.
  const geometry::Mesh millimetres = Rectangle(0, 100, 0, 100, 0);
  ExpectInvalid([&] { EvaluatePointCloud(millimetres, cloud, Options()); }, "millimetres");
}

TEST(Metrics, DistanceStatsInterpolatePercentiles) {
  const DistanceStats stats = Summarize({4, 1, 3, 2, 5});
  EXPECT_EQ(stats.count, 5u);
  EXPECT_DOUBLE_EQ(stats.mean, 3);
  EXPECT_DOUBLE_EQ(stats.median, 3);
  EXPECT_DOUBLE_EQ(stats.p90, 4.6);
  EXPECT_DOUBLE_EQ(stats.max, 5);
  EXPECT_DOUBLE_EQ(stats.rmse, std::sqrt(11.0));
  EXPECT_EQ(Summarize({}).count, 0u);
  EXPECT_DOUBLE_EQ(FScore(0.5, 1.0), 2.0 / 3.0);
  EXPECT_EQ(FScore(0, 0), 0);
}

TEST(Sampling, IsUniformByAreaAndReproducible) {
  // Two sheets, the second four times larger: it must get four times the samples.
  geometry::Mesh mesh = Rectangle(0, 0.05, 0, 0.05, 0, 1, 1);
  mesh.Append(Rectangle(1, 1.1, 0, 0.1, 0, 1, 2));
  const SurfaceSamples a = SampleSurface(mesh, 1e6, 3);
  const SurfaceSamples b = SampleSurface(mesh, 1e6, 3);
  EXPECT_EQ(a.points, b.points);
  size_t on_large = 0;
  for (int32_t face : a.faces) on_large += face >= 2;
  EXPECT_NEAR(static_cast<double>(on_large) / static_cast<double>(a.size()), 0.8, 0.01);
  // Uniform within a triangle: a quarter of a sheet's samples in each quarter.
  size_t lower_left = 0, on_small = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a.faces[i] >= 2) continue;
    ++on_small;
    lower_left += a.points[i].x() < 0.025 && a.points[i].y() < 0.025;
  }
  EXPECT_NEAR(static_cast<double>(lower_left) / static_cast<double>(on_small), 0.25, 0.02);
  EXPECT_NE(SampleSurface(mesh, 1e6, 4).points, a.points);
}

}  // namespace
}  // namespace avc::eval
