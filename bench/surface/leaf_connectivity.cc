#include "bench/surface/leaf_connectivity.h"

#include <map>

#include "core/eval/triangle_tree.h"
#include "core/surface/mesh_topology.h"

namespace avc::bench {

LeafConnectivity CountConnectedLeaves(const geometry::Mesh& truth, const geometry::Mesh& mesh) {
  std::map<int32_t, geometry::Mesh> faces_of_leaf;
  for (int32_t label : truth.face_labels) faces_of_leaf[label];
  if (!mesh.faces.empty()) {
    const eval::TriangleTree tree(truth, "leaf ground truth");
    for (const Eigen::Vector3i& t : mesh.faces) {
      const Eigen::Vector3d centroid =
          (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]).cast<double>() / 3.0;
      geometry::Mesh& leaf = faces_of_leaf[truth.face_labels[tree.Closest(centroid).face]];
      if (leaf.vertices.empty()) leaf.vertices = mesh.vertices;
      leaf.faces.push_back(t);
    }
  }
  LeafConnectivity result;
  for (const auto& [label, leaf] : faces_of_leaf) {
    ++result.leaves;
    int components = 0;
    surface::FaceComponents(leaf, &components);
    if (components == 1) ++result.one_component;
  }
  return result;
}

}  // namespace avc::bench
