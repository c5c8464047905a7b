#pragma once

// The named methods of one comparison row set, each bound to its options and the set's K.

#include <string>
#include <vector>

#include "bench/clustering/comparison_options.h"

namespace avc::bench {

inline constexpr const char* kKMeansName = "k-means";
inline constexpr const char* kIpddpName = "iPDDP";
inline constexpr const char* kDenseSpectralName = "dense spectral";
inline constexpr const char* kSparseSpectralName = "sparse spectral (Lanczos)";
inline constexpr const char* kRegionGrowingName = "region growing (PCL)";

struct ComparedMethod {
  std::string name;
  ClusterFunction run;
  size_t max_points = 0;  // larger sets are skipped; 0: no cap
};

// "ours" first (when given), then the baselines in a fixed order.
std::vector<ComparedMethod> ComparedMethods(const ComparisonOptions& options, int clusters);

}  // namespace avc::bench
