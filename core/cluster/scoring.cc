#include "core/cluster/scoring.h"

#include <map>
#include <stdexcept>
#include <string>

#include "core/cluster/hungarian.h"

namespace avc::cluster {

double CorrectlyClusteredFraction(const Assignment& assignment,
                                  const std::vector<int32_t>& labels) {
  if (assignment.size() != labels.size()) {
    throw std::invalid_argument("CorrectlyClusteredFraction: " + std::to_string(assignment.size()) +
                                " cluster ids for " + std::to_string(labels.size()) + " labels");
  }
  std::map<int32_t, size_t> cluster_index;
  std::map<int32_t, size_t> label_index;
  size_t labelled = 0;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (assignment[i] < kUnassigned || labels[i] < kUnassigned) {
      throw std::invalid_argument("CorrectlyClusteredFraction: id below kUnassigned at point " +
                                  std::to_string(i));
    }
    if (labels[i] == kUnassigned) continue;
    ++labelled;
    label_index.emplace(labels[i], 0);
    if (assignment[i] != kUnassigned) cluster_index.emplace(assignment[i], 0);
  }
  if (labelled == 0) {
    throw std::invalid_argument("CorrectlyClusteredFraction: no point has a ground-truth label");
  }
  size_t k = 0;
  for (auto& entry : cluster_index) entry.second = k++;
  k = 0;
  for (auto& entry : label_index) entry.second = k++;
  if (cluster_index.empty()) return 0.0;

  std::vector<std::vector<double>> overlap(cluster_index.size(),
                                           std::vector<double>(label_index.size(), 0.0));
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == kUnassigned || assignment[i] == kUnassigned) continue;
    overlap[cluster_index[assignment[i]]][label_index[labels[i]]] += 1.0;
  }
  std::vector<std::vector<double>> cost = overlap;
  for (auto& row : cost) {
    for (double& c : row) c = -c;  // maximise the matched points
  }
  const std::vector<int> match = SolveAssignment(cost);
  double correct = 0.0;
  for (size_t r = 0; r < match.size(); ++r) {
    if (match[r] >= 0) correct += overlap[r][static_cast<size_t>(match[r])];
  }
  return correct / static_cast<double>(labelled);
}

}  // namespace avc::cluster
