#include "bench/surface/surface_case.h"

#include <chrono>
#include <functional>
#include <stdexcept>

#include "bench/summary.h"
#include "bench/surface/leaf_connectivity.h"
#include "core/cluster/cluster_plant.h"
#include "core/cluster/data_scale.h"
#include "core/eval/metrics.h"
#include "core/surface/baselines/advancing_front.h"
#include "core/surface/baselines/greedy_projection.h"
#include "core/surface/baselines/poisson_trimmed.h"
#include "core/surface/baselines/pound_patches.h"
#include "core/surface/surface_reconstruction.h"
#include "tests/surface/surface_test_points.h"  // the plant test's leaf sampling, reused

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

SurfaceMethodResult Score(const std::string& method, const geometry::Mesh& truth, int repeats,
                          const Mesher& mesher) {
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
  result.methods.push_back(Score("ours, leaf clusters", truth, n,
                                 [&] { return surface::ReconstructSurface(leaf_clusters).mesh; }));
  result.methods.push_back(Score("ours, Algorithm 2", truth, n,
                                 [&] { return surface::ReconstructSurface(algorithm2).mesh; }));
  result.methods.back().cluster_seconds = cluster_seconds;
  namespace baselines = surface::baselines;
  result.methods.push_back(
      Score("Poisson, trimmed", truth, n, [&] { return baselines::PoissonTrimmed(cloud); }));
  result.methods.push_back(
      Score("greedy projection", truth, n, [&] { return baselines::GreedyProjection(cloud); }));
  result.methods.push_back(
      Score("advancing front", truth, n, [&] { return baselines::AdvancingFront(cloud); }));
  result.methods.push_back(
      Score("Pound patches", truth, n, [&] { return baselines::PoundPatches(cloud); }));
  return result;
}

}  // namespace avc::bench
