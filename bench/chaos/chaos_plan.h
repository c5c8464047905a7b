#pragma once

// Which process a chaos trial kills and when, drawn from a seed: the victims in a balanced shuffle
// (each equally often, within one), the moments uniform over most of an undisturbed scan.

#include <cstdint>
#include <string>
#include <vector>

#include "bench/chaos/chaos_scan.h"

namespace avc::bench {

struct ChaosPlanOptions {
  int trials = 20;
  uint64_t seed = 1;
  std::vector<std::string> victims = ChaosVictims();
  double scan_wall_s = 0;  // how long the undisturbed scan took
  // Moments are uniform in [first, last] times scan_wall_s, and never before min_s.
  double first = 0.05, last = 0.90;
  double min_s = 2;
};

// The same faults for the same options, with every standard library (our own mapping of the
// engine's bits). Throws std::invalid_argument when there are no victims or no trials.
std::vector<ChaosFault> PlanChaosFaults(const ChaosPlanOptions& options);

}  // namespace avc::bench
