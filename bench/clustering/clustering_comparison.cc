#include "bench/clustering/clustering_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>

#include "bench/clustering/compared_methods.h"

namespace avc::bench {
namespace {

int ClusterCount(const cluster::PointSet& set, const ComparisonOptions& options) {
  if (options.clusters > 0) return options.clusters;
  std::set<int32_t> distinct(set.labels.begin(), set.labels.end());
  distinct.erase(cluster::kUnassigned);
  if (distinct.empty()) {
    throw std::invalid_argument(fmt::format(
        "clustering comparison: set '{}' has no labels, so options.clusters must be given",
        set.name));
  }
  return static_cast<int>(distinct.size());
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

nlohmann::json RunOne(const ComparedMethod& method, const cluster::PointSet& set,
                      const ComparisonOptions& options) {
  nlohmann::json result = {{"set", set.name}};
  if (method.max_points > 0 && set.points.size() > method.max_points) {
    result["status"] = "skipped";
    result["reason"] = fmt::format("{} points > cap {}", set.points.size(), method.max_points);
    return result;
  }
  std::vector<double> runs_ms;
  cluster::Assignment first;
  bool repeatable = true;
  try {
    for (int r = 0; r < options.repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      cluster::Assignment assignment = method.run(set);
      const std::chrono::duration<double, std::milli> elapsed =
          std::chrono::steady_clock::now() - start;
      runs_ms.push_back(elapsed.count());
      if (assignment.size() != set.points.size()) {
        throw std::runtime_error(
            fmt::format("returned {} ids for {} points", assignment.size(), set.points.size()));
      }
      if (r == 0) {
        first = std::move(assignment);
        if (elapsed.count() > options.single_run_above_ms) break;
      } else if (assignment != first) {
        repeatable = false;
      }
    }
  } catch (const std::exception& e) {
    result["status"] = "error";
    result["reason"] = e.what();
    return result;
  }
  std::set<int32_t> found(first.begin(), first.end());
  found.erase(cluster::kUnassigned);
  result["status"] = "ok";
  result["accuracy"] = options.score && !set.labels.empty()
                           ? nlohmann::json(options.score(first, set.labels))
                           : nlohmann::json(nullptr);
  result["median_ms"] = Median(runs_ms);
  result["runs_ms"] = runs_ms;
  result["clusters_found"] = found.size();
  result["unassigned"] = std::count(first.begin(), first.end(), cluster::kUnassigned);
  result["repeatable"] = repeatable;
  return result;
}

// Median time of method `name` on set index s, or null when it did not run.
nlohmann::json MedianMs(const nlohmann::json& methods, const std::string& name, size_t s) {
  for (const nlohmann::json& method : methods) {
    if (method["name"] != name) continue;
    const nlohmann::json& result = method["results"][s];
    return result["status"] == "ok" ? result["median_ms"] : nlohmann::json(nullptr);
  }
  return nullptr;
}

nlohmann::json Ratio(const nlohmann::json& slow, const nlohmann::json& fast) {
  if (slow.is_null() || fast.is_null() || fast.get<double>() <= 0) return nullptr;
  return slow.get<double>() / fast.get<double>();
}

}  // namespace

nlohmann::json RunClusteringComparison(const std::vector<cluster::PointSet>& sets,
                                       const ComparisonOptions& options) {
  if (options.repeats < 1) {
    throw std::invalid_argument("clustering comparison: repeats must be >= 1");
  }
  nlohmann::json report = {{"benchmark", "clustering"},
                           {"repeats", options.repeats},
                           {"dense_spectral_max_points", options.dense_spectral_max_points},
                           {"sets", nlohmann::json::array()},
                           {"methods", nlohmann::json::array()},
                           {"speed_ratios", nlohmann::json::array()}};
  std::vector<int> clusters;
  for (const cluster::PointSet& set : sets) {
    clusters.push_back(ClusterCount(set, options));
    report["sets"].push_back({{"name", set.name},
                              {"points", set.points.size()},
                              {"clusters", clusters.back()},
                              {"labelled", !set.labels.empty()}});
  }
  // Method names and order do not depend on K, so the first set's list names the rows.
  for (const ComparedMethod& method : ComparedMethods(options, 1)) {
    report["methods"].push_back({{"name", method.name}, {"results", nlohmann::json::array()}});
  }
  for (size_t s = 0; s < sets.size(); ++s) {
    const std::vector<ComparedMethod> methods = ComparedMethods(options, clusters[s]);
    for (size_t m = 0; m < methods.size(); ++m) {
      report["methods"][m]["results"].push_back(RunOne(methods[m], sets[s], options));
    }
  }
  for (size_t s = 0; s < sets.size(); ++s) {
    const nlohmann::json ours =
        options.ours ? MedianMs(report["methods"], options.ours_name, s) : nlohmann::json(nullptr);
    report["speed_ratios"].push_back(
        {{"set", sets[s].name},
         {"dense_spectral_over_ours",
          Ratio(MedianMs(report["methods"], kDenseSpectralName, s), ours)},
         {"sparse_spectral_over_ours",
          Ratio(MedianMs(report["methods"], kSparseSpectralName, s), ours)}});
  }
  return report;
}

}  // namespace avc::bench
