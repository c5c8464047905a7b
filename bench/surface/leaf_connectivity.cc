#include "bench/surface/leaf_connectivity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <unordered_map>

#include "core/eval/triangle_tree.h"
#include "core/surface/mesh_topology.h"

namespace avc::bench {
namespace {

// The leaves each face may belong to: its nearest, then any within kAmbiguity of that.
struct FaceLeaves {
  std::vector<int32_t> nearest;
  std::vector<std::vector<int32_t>> candidates;  // empty when unambiguous
};

// One search tree per leaf, with its bounding box to skip leaves too far to matter.
class LeafTrees {
 public:
  explicit LeafTrees(const geometry::Mesh& truth) {
    std::map<int32_t, geometry::Mesh> leaves;
    for (size_t f = 0; f < truth.faces.size(); ++f) {
      geometry::Mesh& leaf = leaves[truth.face_labels[f]];
      if (leaf.vertices.empty()) leaf.vertices = truth.vertices;
      leaf.faces.push_back(truth.faces[f]);
    }
    for (auto& [label, leaf] : leaves) {
      surface::RemoveUnusedVertices(leaf);
      Eigen::AlignedBox3d box;
      for (const Eigen::Vector3f& v : leaf.vertices) box.extend(v.cast<double>());
      labels_.push_back(label);
      boxes_.push_back(box);
      trees_.push_back(std::make_unique<eval::TriangleTree>(leaf, "leaf ground truth"));
    }
  }

  // Labels within kAmbiguity of the nearest leaf's distance (the nearest first).
  std::vector<int32_t> Near(const Eigen::Vector3d& point) const {
    std::vector<double> distance(trees_.size(), -1.0);
    size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < trees_.size(); ++k) {
      if (boxes_[k].exteriorDistance(point) > best_distance + kAmbiguity) continue;
      distance[k] = trees_[k]->Closest(point).distance;
      if (distance[k] < best_distance) {
        best_distance = distance[k];
        best = k;
      }
    }
    std::vector<int32_t> near = {labels_[best]};
    for (size_t k = 0; k < trees_.size(); ++k) {
      // Leaves skipped above (distance -1) are farther than that from the point.
      if (k != best && distance[k] >= 0.0 && distance[k] <= best_distance + kAmbiguity) {
        near.push_back(labels_[k]);
      }
    }
    return near;
  }

 private:
  std::vector<int32_t> labels_;
  std::vector<Eigen::AlignedBox3d> boxes_;
  std::vector<std::unique_ptr<eval::TriangleTree>> trees_;
};

FaceLeaves AttributeFaces(const geometry::Mesh& truth, const geometry::Mesh& mesh) {
  const LeafTrees trees(truth);
  FaceLeaves leaves;
  leaves.nearest.resize(mesh.faces.size());
  leaves.candidates.resize(mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    const Eigen::Vector3d centroid =
        (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]).cast<double>() / 3.0;
    std::vector<int32_t> near = trees.Near(centroid);
    leaves.nearest[f] = near.front();
    if (near.size() > 1) leaves.candidates[f] = std::move(near);
  }
  return leaves;
}

// The faces across each edge of each face (edges with exactly two faces).
std::vector<std::vector<int>> EdgeNeighbours(const geometry::Mesh& mesh) {
  std::unordered_map<uint64_t, std::vector<int>> faces_of_edge;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      faces_of_edge[surface::EdgeKey(t[k], t[(k + 1) % 3])].push_back(static_cast<int>(f));
    }
  }
  std::vector<std::vector<int>> across(mesh.faces.size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      const std::vector<int>& sharing = faces_of_edge[surface::EdgeKey(t[k], t[(k + 1) % 3])];
      if (sharing.size() != 2) continue;
      across[f].push_back(sharing[0] == static_cast<int>(f) ? sharing[1] : sharing[0]);
    }
  }
  return across;
}

// Breadth first from the unambiguous faces (in face order: deterministic).
std::vector<int32_t> SettleOnMesh(const geometry::Mesh& mesh, const FaceLeaves& leaves) {
  std::vector<int32_t> leaf = leaves.nearest;
  std::vector<bool> settled(leaf.size());
  std::deque<int> front;
  for (size_t f = 0; f < leaf.size(); ++f) {
    settled[f] = leaves.candidates[f].empty();
    if (settled[f]) front.push_back(static_cast<int>(f));
  }
  const std::vector<std::vector<int>> across = EdgeNeighbours(mesh);
  while (!front.empty()) {
    const int f = front.front();
    front.pop_front();
    for (int g : across[f]) {
      if (settled[g]) continue;
      const std::vector<int32_t>& options = leaves.candidates[g];
      if (std::find(options.begin(), options.end(), leaf[f]) == options.end()) continue;
      leaf[g] = leaf[f];
      settled[g] = true;
      front.push_back(g);
    }
  }
  return leaf;
}

struct PieceCounts {
  int one_piece = 0;   // leaves whose faces form exactly one component
  int mostly_one = 0;  // ... whose largest component holds >= kMostlyOne of their area
};
constexpr double kMostlyOne = 0.95;

PieceCounts CountPieces(const std::map<int32_t, int>& counted, const geometry::Mesh& mesh,
                        const std::vector<int32_t>& leaf_of_face) {
  std::map<int32_t, geometry::Mesh> faces_of_leaf;
  for (const auto& [label, unused] : counted) faces_of_leaf[label];
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    if (!counted.contains(leaf_of_face[f])) continue;
    geometry::Mesh& leaf = faces_of_leaf[leaf_of_face[f]];
    if (leaf.vertices.empty()) leaf.vertices = mesh.vertices;
    leaf.faces.push_back(mesh.faces[f]);
  }
  PieceCounts counts;
  for (const auto& [label, leaf] : faces_of_leaf) {
    int components = 0;
    const std::vector<int> component = surface::FaceComponents(leaf, &components);
    if (components == 1) ++counts.one_piece;
    std::vector<double> area(components, 0.0);
    double total = 0.0;
    for (size_t f = 0; f < leaf.faces.size(); ++f) {
      const double a = geometry::FaceArea(leaf, leaf.faces[f]);
      area[component[f]] += a;
      total += a;
    }
    if (components > 0 && *std::max_element(area.begin(), area.end()) >= kMostlyOne * total) {
      ++counts.mostly_one;
    }
  }
  return counts;
}

}  // namespace

LeafConnectivity CountConnectedLeaves(const geometry::Mesh& truth, const geometry::Mesh& mesh,
                                      bool leaf_labels_only) {
  LeafConnectivity result;
  std::map<int32_t, int> leaves;
  for (int32_t label : truth.face_labels) {
    if (!leaf_labels_only || geometry::labels::IsLeaf(label)) leaves[label];
  }
  result.leaves = static_cast<int>(leaves.size());
  if (mesh.faces.empty()) return result;
  const FaceLeaves attribution = AttributeFaces(truth, mesh);
  result.one_component_strict = CountPieces(leaves, mesh, attribution.nearest).one_piece;
  const PieceCounts settled = CountPieces(leaves, mesh, SettleOnMesh(mesh, attribution));
  result.one_component = settled.one_piece;
  result.mostly_one = settled.mostly_one;
  return result;
}

}  // namespace avc::bench
