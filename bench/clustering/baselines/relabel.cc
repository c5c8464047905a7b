#include "bench/clustering/baselines/relabel.h"

#include <unordered_map>

namespace avc::cluster::baselines {

Assignment RelabelByFirstAppearance(const Assignment& assignment) {
  std::unordered_map<int32_t, int32_t> renamed;
  Assignment result(assignment.size(), kUnassigned);
  for (size_t i = 0; i < assignment.size(); ++i) {
    if (assignment[i] == kUnassigned) continue;
    auto [it, inserted] = renamed.try_emplace(assignment[i], static_cast<int32_t>(renamed.size()));
    result[i] = it->second;
  }
  return result;
}

}  // namespace avc::cluster::baselines
