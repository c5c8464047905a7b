#include "bench/clustering/table2_sets.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>

#include "core/geometry/mesh.h"
#include "core/util/ordered_draws.h"
#include "sim/scene/plant.h"

namespace avc::cluster {
namespace {

namespace labels = geometry::labels;

constexpr float kPositionNoise = 0.0002f;  // m, per axis
constexpr float kNormalNoise = 0.05f;      // rad, per axis (about 3 degrees in total)
constexpr double kOutlierFraction = 0.02;
constexpr float kOutlierMargin = 0.01f;  // m

// Uniform in [0, 1) from the top 53 bits (identical on every standard library).
double Uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Approximately standard normal: Irwin-Hall sum of four uniforms, rescaled to unit variance.
float Gaussian(std::mt19937_64& rng) {
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += Uniform(rng);
  return static_cast<float>((sum - 2.0) * std::sqrt(3.0));
}

// The label a face contributes under the set's organ choice, or kUnassigned to skip it.
using FaceLabel = std::map<int32_t, int32_t>;  // organ label -> ground-truth label

PointSet SampleOrgans(const std::string& name, const geometry::Mesh& mesh, const FaceLabel& keep,
                      uint64_t seed) {
  std::vector<size_t> faces;
  std::vector<double> cumulative;
  double area = 0.0;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    if (!keep.count(mesh.face_labels[f])) continue;
    const Eigen::Vector3i& t = mesh.faces[f];
    const Eigen::Vector3f e1 = mesh.vertices[t[1]] - mesh.vertices[t[0]];
    const Eigen::Vector3f e2 = mesh.vertices[t[2]] - mesh.vertices[t[0]];
    const double a = 0.5 * e1.cross(e2).norm();
    if (!(a > 0.0)) continue;
    area += a;
    faces.push_back(f);
    cumulative.push_back(area);
  }
  if (faces.empty()) throw std::logic_error("Table2Sets: set " + name + " selected no faces");

  std::mt19937_64 rng(seed);
  PointSet set;
  set.name = name;
  for (int s = 0; s < kTable2SurfacePoints; ++s) {
    const double pick = Uniform(rng) * area;
    const size_t k = std::min<size_t>(
        faces.size() - 1,
        static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) -
                            cumulative.begin()));
    const Eigen::Vector3i& t = mesh.faces[faces[k]];
    const Eigen::Vector3f& a = mesh.vertices[t[0]];
    const Eigen::Vector3f& b = mesh.vertices[t[1]];
    const Eigen::Vector3f& c = mesh.vertices[t[2]];
    // Uniform on the triangle: sqrt warp of the first coordinate.
    const float r1 = static_cast<float>(std::sqrt(Uniform(rng)));
    const float r2 = static_cast<float>(Uniform(rng));
    Eigen::Vector3f p = (1.0f - r1) * a + r1 * (1.0f - r2) * b + r1 * r2 * c;
    Eigen::Vector3f n = (b - a).cross(c - a).normalized();
    const auto gaussian = [&] { return Gaussian(rng); };
    p += kPositionNoise * util::DrawVector3<Eigen::Vector3f>(gaussian);
    n = (n + kNormalNoise * util::DrawVector3<Eigen::Vector3f>(gaussian)).normalized();
    set.points.push_back(p);
    set.normals.push_back(n);
    set.labels.push_back(keep.at(mesh.face_labels[faces[k]]));
  }

  Eigen::Vector3f lo = set.points[0];
  Eigen::Vector3f hi = set.points[0];
  for (const Eigen::Vector3f& p : set.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  lo.array() -= kOutlierMargin;
  hi.array() += kOutlierMargin;
  const int outliers = static_cast<int>(std::lround(kOutlierFraction * kTable2SurfacePoints));
  for (int s = 0; s < outliers; ++s) {
    Eigen::Vector3f p;
    for (int axis = 0; axis < 3; ++axis) {
      p[axis] = lo[axis] + static_cast<float>(Uniform(rng)) * (hi[axis] - lo[axis]);
    }
    Eigen::Vector3f n = util::DrawVector3<Eigen::Vector3f>([&] { return Gaussian(rng); });
    if (n.norm() < 1e-3f) n = Eigen::Vector3f::UnitZ();
    set.points.push_back(p);
    set.normals.push_back(n.normalized());
    set.labels.push_back(kUnassigned);
  }
  return set;
}

struct LeafInfo {
  int32_t label = 0;
  double area = 0.0;
  double top = -std::numeric_limits<double>::infinity();  // highest vertex z
  std::vector<Eigen::Vector3f> vertices;
};

std::vector<LeafInfo> Leaves(const geometry::Mesh& mesh) {
  std::map<int32_t, LeafInfo> leaves;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const int32_t label = mesh.face_labels[f];
    if (!labels::IsLeaf(label)) continue;
    LeafInfo& leaf = leaves[label];
    leaf.label = label;
    const Eigen::Vector3i& t = mesh.faces[f];
    const Eigen::Vector3f& a = mesh.vertices[t[0]];
    leaf.area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
    for (int k = 0; k < 3; ++k) {
      leaf.top = std::max(leaf.top, static_cast<double>(mesh.vertices[t[k]].z()));
      leaf.vertices.push_back(mesh.vertices[t[k]]);
    }
  }
  std::vector<LeafInfo> out;
  for (auto& entry : leaves) out.push_back(std::move(entry.second));
  return out;
}

double Gap(const LeafInfo& a, const LeafInfo& b) {
  double best = std::numeric_limits<double>::infinity();
  // Every 7th vertex: close enough to rank pairs, 50x cheaper than all pairs.
  for (size_t i = 0; i < a.vertices.size(); i += 7) {
    for (size_t j = 0; j < b.vertices.size(); j += 7) {
      best = std::min(best, static_cast<double>((a.vertices[i] - b.vertices[j]).squaredNorm()));
    }
  }
  return std::sqrt(best);
}

std::vector<int32_t> ClosestPair(const std::vector<LeafInfo>& leaves) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<int32_t> pair;
  for (size_t i = 0; i < leaves.size(); ++i) {
    for (size_t j = i + 1; j < leaves.size(); ++j) {
      const double gap = Gap(leaves[i], leaves[j]);
      if (gap < best) {
        best = gap;
        pair = {leaves[i].label, leaves[j].label};
      }
    }
  }
  return pair;
}

std::vector<int32_t> Highest(std::vector<LeafInfo> leaves, size_t count) {
  std::stable_sort(leaves.begin(), leaves.end(),
                   [](const LeafInfo& a, const LeafInfo& b) { return a.top > b.top; });
  std::vector<int32_t> out;
  for (size_t k = 0; k < std::min(count, leaves.size()); ++k) out.push_back(leaves[k].label);
  return out;
}

FaceLabel KeepLeaves(const std::vector<int32_t>& leaves, bool with_stem) {
  FaceLabel keep;
  for (int32_t label : leaves) keep[label] = label;
  if (with_stem) {
    keep[labels::kStem] = labels::kStem;
  }
  return keep;
}

}  // namespace

std::vector<PointSet> Table2Sets(uint64_t seed) {
  const auto plant_seed = [&](uint32_t salt) {
    return static_cast<uint32_t>((seed * 0x9E3779B97F4A7C15ull + salt) >> 32);
  };
  const sim::Scene broadleaf = sim::GeneratePlant(sim::PlantPreset::kBroadleaf, plant_seed(1));
  const sim::Scene bushy = sim::GeneratePlant(sim::PlantPreset::kBushy, plant_seed(2));
  const std::vector<LeafInfo> broad_leaves = Leaves(broadleaf.mesh);
  const std::vector<LeafInfo> bushy_leaves = Leaves(bushy.mesh);

  const auto largest =
      std::max_element(broad_leaves.begin(), broad_leaves.end(),
                       [](const LeafInfo& a, const LeafInfo& b) { return a.area < b.area; });
  const std::vector<int32_t> pair = ClosestPair(broad_leaves);

  std::vector<PointSet> sets;
  const uint64_t sample_seed = seed * 0xD1B54A32D192ED03ull;
  sets.push_back(SampleOrgans("A one-leaf", broadleaf.mesh, KeepLeaves({largest->label}, false),
                              sample_seed + 1));
  sets.push_back(
      SampleOrgans("B leaf-pair", broadleaf.mesh, KeepLeaves(pair, false), sample_seed + 2));
  sets.push_back(
      SampleOrgans("C leaves-on-stem", broadleaf.mesh, KeepLeaves(pair, true), sample_seed + 3));
  sets.push_back(SampleOrgans("D crowded-crown", broadleaf.mesh,
                              KeepLeaves(Highest(broad_leaves, 6), true), sample_seed + 4));
  sets.push_back(SampleOrgans("E bushy-top", bushy.mesh,
                              KeepLeaves(Highest(bushy_leaves, 8), false), sample_seed + 5));
  sets.push_back(SampleOrgans("F bushy-canopy", bushy.mesh,
                              KeepLeaves(Highest(bushy_leaves, 12), false), sample_seed + 6));
  return sets;
}

int CountClusters(const PointSet& set) {
  std::set<int32_t> distinct;
  for (int32_t label : set.labels) {
    if (label != kUnassigned) distinct.insert(label);
  }
  return static_cast<int>(distinct.size());
}

}  // namespace avc::cluster
