#include "bench/chaos/chaos_plan.h"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <utility>

namespace avc::bench {
namespace {

// std::uniform_*_distribution differ between standard libraries; these do not.
double Unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
size_t Below(std::mt19937_64& rng, size_t n) { return static_cast<size_t>(Unit(rng) * n); }

}  // namespace

std::vector<ChaosFault> PlanChaosFaults(const ChaosPlanOptions& options) {
  if (options.victims.empty()) throw std::invalid_argument("no process to kill");
  if (options.trials < 1) throw std::invalid_argument("no trials");
  std::mt19937_64 rng(options.seed);
  // Rounds of every victim once, each round shuffled (Fisher-Yates): balanced and unpredictable.
  std::vector<std::string> order;
  while (order.size() < static_cast<size_t>(options.trials)) {
    std::vector<std::string> round = options.victims;
    for (size_t i = round.size() - 1; i > 0; --i) std::swap(round[i], round[Below(rng, i + 1)]);
    order.insert(order.end(), round.begin(), round.end());
  }
  order.resize(static_cast<size_t>(options.trials));
  std::vector<ChaosFault> faults;
  for (std::string& victim : order) {
    const double fraction = options.first + (options.last - options.first) * Unit(rng);
    faults.push_back({std::move(victim), std::max(options.min_s, fraction * options.scan_wall_s)});
  }
  return faults;
}

}  // namespace avc::bench
