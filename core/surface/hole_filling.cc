#include "core/surface/hole_filling.h"

#include <vector>

#include "core/surface/mesh_topology.h"

namespace avc::surface {
namespace {

void CloseLoop(geometry::Mesh& mesh, const BoundaryLoop& loop) {
  const int32_t label = mesh.face_labels.empty() ? 0 : mesh.face_labels[loop.faces[0]];
  const size_t n = loop.vertices.size();
  // Boundary half-edges run a -> b in their face; the filling face runs b -> a.
  auto add_face = [&](int a, int b, int c) {
    mesh.faces.emplace_back(a, b, c);
    if (!mesh.face_labels.empty()) mesh.face_labels.push_back(label);
    if (!mesh.face_materials.empty()) mesh.face_materials.push_back(0);
  };
  if (n == 3) {
    add_face(loop.vertices[2], loop.vertices[1], loop.vertices[0]);
    return;
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d colour = Eigen::Vector3d::Zero();
  for (int v : loop.vertices) {
    centroid += mesh.vertices[v].cast<double>();
    if (!mesh.colors.empty()) colour += mesh.colors[v].cast<double>();
  }
  const int centre = static_cast<int>(mesh.vertices.size());
  mesh.vertices.push_back((centroid / static_cast<double>(n)).cast<float>());
  if (!mesh.colors.empty()) {
    mesh.colors.push_back((colour / static_cast<double>(n)).array().round().cast<uint8_t>());
  }
  if (!mesh.uvs.empty()) mesh.uvs.emplace_back(0.0f, 0.0f);
  for (size_t i = 0; i < n; ++i) {
    add_face(loop.vertices[(i + 1) % n], loop.vertices[i], centre);
  }
}

}  // namespace

size_t FillSmallHoles(geometry::Mesh& mesh, double max_perimeter) {
  const std::vector<BoundaryLoop> loops = BoundaryLoops(mesh);
  const std::vector<bool> outer = OuterLoops(mesh, loops);
  size_t filled = 0;
  for (size_t i = 0; i < loops.size(); ++i) {
    const BoundaryLoop& loop = loops[i];
    if (!loop.closed || outer[i] || loop.vertices.size() < 3) continue;
    if (loop.Perimeter(mesh) > max_perimeter) continue;
    CloseLoop(mesh, loop);
    ++filled;
  }
  return filled;
}

}  // namespace avc::surface
