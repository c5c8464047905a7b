#pragma once

// A chaos run against the undisturbed reference run of the same scan: every image exactly once,
// the same kept images byte for byte, the same mesh byte for byte.

#include <string>
#include <vector>

#include "bench/chaos/chaos_scan.h"

namespace avc::bench {

struct ChaosComparison {
  std::vector<std::string> lost;        // image ids of the reference the run lacks
  std::vector<std::string> duplicated;  // image ids the run recorded more than once
  std::vector<std::string> extra;       // image ids the reference does not have
  size_t recaptured = 0;                // frames rendered beyond the captures kept on record
  bool kept_identical = false;          // the same kept images (ids and sha256), in order
  bool mesh_identical = false;          // mesh.ply byte for byte
  std::vector<std::string> problems;    // every failed check, one sentence each

  bool ok() const { return problems.empty(); }
};

// Compares run with reference. A run's simulator may render one frame again per injected fault
// (a kill between the shutter and the record); an undisturbed one renders each exactly once.
ChaosComparison CompareWithReference(const ChaosScanResult& reference, const ChaosScanResult& run);

}  // namespace avc::bench
