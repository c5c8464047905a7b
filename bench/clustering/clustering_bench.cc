#include "bench/clustering/clustering_bench.h"

#include <CLI/CLI.hpp>
#include <iostream>

#include "bench/clustering/clustering_comparison.h"
#include "bench/clustering/clustering_table.h"
#include "bench/clustering/table2_sets.h"
#include "bench/registry.h"
#include "core/cluster/cluster_plant.h"
#include "core/cluster/scoring.h"

namespace avc::bench {

int RunClusteringBenchmark(const std::vector<std::string>& arguments) {
  uint64_t seed = 1;
  int repeats = 3;
  bool full = false;
  bool json = false;
  CLI::App app{
      "avc bench clustering: the paper's Table 2 replica. Six labelled point sets from the\n"
      "simulated plants (1 to 12 clusters, touching leaves, a stem, 2 % outliers, ~3000 points):\n"
      "our Algorithm 2 against k-means, iPDDP, dense and sparse spectral, PCL region growing.",
      "avc bench clustering"};
  app.add_option("--seed", seed, "plant and sampling seed of the sets")->capture_default_str();
  app.add_option("--repeats", repeats, "timed runs per method and set (median reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_flag("--full", full,
               "run dense spectral on every set too (about 45 s per 3000-point set)");
  app.add_flag("--json", json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;

  ComparisonOptions options;
  options.ours = [](const cluster::PointSet& set) { return cluster::ClusterPlant(set); };
  options.ours_name = "ours (Algorithm 2)";
  options.score = cluster::CorrectlyClusteredFraction;
  options.repeats = repeats;
  options.dense_spectral_max_points = full ? 0 : 1500;
  std::cerr << "building the six sets (seed " << seed << ")\n";
  const nlohmann::json report = RunClusteringComparison(cluster::Table2Sets(seed), options);
  std::cout << FormatClusteringTable(report);
  if (json) std::cout << report.dump() << "\n";
  return 0;
}

}  // namespace avc::bench
