#include "bench/surface/surface_case.h"

#include <chrono>
#include <functional>
#include <stdexcept>

#include "bench/mvs/plant_organs.h"
#include "bench/summary.h"
#include "bench/surface/baselines/advancing_front.h"
#include "bench/surface/baselines/greedy_projection.h"
#include "bench/surface/baselines/poisson_trimmed.h"
#include "bench/surface/baselines/pound_patches.h"
#include "bench/surface/leaf_connectivity.h"
#include "core/cluster/cluster_plant.h"
#include "core/cluster/data_scale.h"
#include "core/eval/metrics.h"
#include "core/surface/surface_reconstruction.h"
#include "core/traits/plant_traits.h"
#include "tests/core/surface/surface_test_points.h"  // the plant test's leaf sampling, reused

namespace avc::bench {
namespace {

using Mesher = std::function<geometry::Mesh()>;

// Runs mesher `repeats` times; returns the last mesh and the median wall time.
geometry::Mesh TimeMedian(int repeats, const Mesher& mesher, double* seconds) {
  std::vector<double> times;
  geometry::Mesh mesh;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    mesh = mesher();
    times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  *seconds = Summarize(times).median;
  return mesh;
}

// The leaves' height above the soil, which the height trait of each mesh is compared with.
struct HeightTruth {
  double ground_z = 0;  // m: the soil's mean height
  double height = 0;    // m: the leaves' top above it
};

SurfaceMethodResult Score(const std::string& method, const geometry::Mesh& truth,
                          const HeightTruth& height, int repeats, const Mesher& mesher) {
  SurfaceMethodResult result;
  result.method = method;
  try {
    const geometry::Mesh mesh = TimeMedian(repeats, mesher, &result.seconds);
    result.faces = mesh.faces.size();
    const eval::EvalResult eval = eval::EvaluateMesh(truth, mesh, eval::EvalOptions{});
    result.area_ratio = eval.area_ratio.value_or(0.0);
    result.rmse = eval.accuracy.rmse;
    result.mean = eval.accuracy.mean;
    const LeafConnectivity leaves = CountConnectedLeaves(truth, mesh);
    result.leaves = leaves.leaves;
    result.connected_leaves = leaves.one_component;
    result.connected_leaves_strict = leaves.one_component_strict;
    result.connected_fraction = leaves.Fraction();
    traits::TraitOptions traits;
    traits.ground_z = height.ground_z;
    result.height_ratio = traits::MeasureTraits(mesh, traits).height / height.height;
    result.ok = true;
  } catch (const std::exception& error) {
    result.error = error.what();
  }
  return result;
}

}  // namespace

SurfaceCaseResult RunSurfaceCase(sim::PlantPreset preset, const SurfaceCaseOptions& options) {
  const sim::Scene scene = sim::GeneratePlant(preset, options.seed);
  geometry::Mesh truth;
  const surface::ClusteredPoints leaf_clusters =
      surface::test::SampleLeaves(scene.mesh, options.points, options.noise, options.seed, &truth);
  surface::ClusteredPoints algorithm2 = leaf_clusters;
  cluster::PointSet set;
  set.points = leaf_clusters.cloud.positions;
  set.normals = leaf_clusters.cloud.normals;
  double cluster_seconds = 0.0;
  {
    std::vector<double> times;
    for (int r = 0; r < options.repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      algorithm2.clusters = cluster::ClusterPlant(set);
      times.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    cluster_seconds = Summarize(times).median;
  }

  SurfaceCaseResult result;
  result.preset = std::string(sim::PresetName(preset));
  result.points = leaf_clusters.cloud.size();
  result.spacing = cluster::EstimateDataScale(leaf_clusters.cloud.positions).spacing;
  result.truth_area = geometry::SurfaceArea(truth);
  const geometry::PointCloud& cloud = leaf_clusters.cloud;
  const int n = options.repeats;
  HeightTruth height;
  height.ground_z = MeasureTruthTraits(scene.mesh).ground_z;
  traits::TraitOptions traits;
  traits.ground_z = height.ground_z;
  height.height = traits::MeasureTraits(truth, traits).height;
  result.methods.push_back(Score("ours, leaf clusters", truth, height, n,
                                 [&] { return surface::ReconstructSurface(leaf_clusters).mesh; }));
  result.methods.push_back(Score("ours, Algorithm 2", truth, height, n,
                                 [&] { return surface::ReconstructSurface(algorithm2).mesh; }));
  result.methods.back().cluster_seconds = cluster_seconds;
  namespace baselines = surface::baselines;
  result.methods.push_back(Score("Poisson, trimmed", truth, height, n,
                                 [&] { return baselines::PoissonTrimmed(cloud); }));
  result.methods.push_back(Score("greedy projection", truth, height, n,
                                 [&] { return baselines::GreedyProjection(cloud); }));
  result.methods.push_back(
      Score("advancing front", truth, height, n, [&] { return baselines::AdvancingFront(cloud); }));
  result.methods.push_back(
      Score("Pound patches", truth, height, n, [&] { return baselines::PoundPatches(cloud); }));
  return result;
}

}  // namespace avc::bench
