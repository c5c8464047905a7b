#include "tests/bench/clustering/baselines/synthetic_sets.h"

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>

#include "core/util/ordered_draws.h"

namespace avc::cluster::testing {
namespace {

// Uniform in [-1, 1) from raw bits: identical on every standard library.
float Symmetric(std::mt19937& rng) {
  return static_cast<float>(static_cast<double>(rng() >> 8) * 0x1.0p-23 - 1.0);
}

}  // namespace

PointSet Blobs(int clusters, int points_each, uint32_t seed) {
  std::mt19937 rng(seed);
  PointSet set;
  set.name = "blobs";
  for (int c = 0; c < clusters; ++c) {
    const Eigen::Vector3f centre(0.1f * static_cast<float>(c), 0.02f * static_cast<float>(c % 2),
                                 0.0f);
    for (int i = 0; i < points_each; ++i) {
      Eigen::Vector3f offset;
      do {
        offset = util::DrawVector3<Eigen::Vector3f>([&] { return Symmetric(rng); });
      } while (offset.squaredNorm() > 1.0f || offset.squaredNorm() < 1e-4f);
      set.points.push_back(centre + 0.01f * offset);
      set.normals.push_back(offset.normalized());
      set.labels.push_back(c);
    }
  }
  return set;
}

PointSet OrthogonalPatches(int points_each, uint32_t seed) {
  std::mt19937 rng(seed);
  PointSet set;
  set.name = "patches";
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3f centre = Eigen::Vector3f::Zero();
    centre[axis] = 0.1f;
    for (int i = 0; i < points_each; ++i) {
      Eigen::Vector3f p = centre;
      p[(axis + 1) % 3] += 0.03f * Symmetric(rng);
      p[(axis + 2) % 3] += 0.03f * Symmetric(rng);
      p[axis] += 0.0002f * Symmetric(rng);
      set.points.push_back(p);
      set.normals.push_back(Eigen::Vector3f::Unit(axis));
      set.labels.push_back(axis);
    }
  }
  return set;
}

PointSet ConcentricRings(int points_each, uint32_t seed) {
  std::mt19937 rng(seed);
  PointSet set;
  set.name = "rings";
  for (int ring = 0; ring < 2; ++ring) {
    const float radius = ring == 0 ? 0.05f : 0.15f;
    for (int i = 0; i < points_each; ++i) {
      const float angle = 2.0f * std::numbers::pi_v<float> *
                          (static_cast<float>(i) + 0.5f * Symmetric(rng)) /
                          static_cast<float>(points_each);
      const Eigen::Vector3f radial(std::cos(angle), std::sin(angle), 0.0f);
      set.points.push_back(radius * radial + 0.001f * util::DrawVector3<Eigen::Vector3f>(
                                                          [&] { return Symmetric(rng); }));
      set.normals.push_back(radial);
      set.labels.push_back(ring);
    }
  }
  return set;
}

double Purity(const Assignment& assignment, const std::vector<int32_t>& labels) {
  std::map<int32_t, std::map<int32_t, int>> counts;  // cluster -> label -> points
  for (size_t i = 0; i < assignment.size(); ++i) {
    if (assignment[i] != kUnassigned) ++counts[assignment[i]][labels[i]];
  }
  int correct = 0;
  for (const auto& [cluster, by_label] : counts) {
    int best = 0;
    for (const auto& [label, count] : by_label) best = std::max(best, count);
    correct += best;
  }
  return static_cast<double>(correct) / static_cast<double>(labels.size());
}

int ClusterCount(const Assignment& assignment) {
  std::set<int32_t> ids(assignment.begin(), assignment.end());
  ids.erase(kUnassigned);
  return static_cast<int>(ids.size());
}

}  // namespace avc::cluster::testing
