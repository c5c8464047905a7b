#pragma once

// Edge and boundary structure of a triangle mesh, computed on demand (meshes here are small:
// thousands of faces). Everything is ordered by vertex and face index: deterministic.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/geometry/mesh.h"

namespace avc::surface {

// A boundary loop: vertices in the direction of the faces' half-edges (counter-clockwise round
// a sheet's outer boundary seen from its front, clockwise round a hole); edge i runs from
// vertices[i] to vertices[i + 1] (cyclically) and belongs to faces[i].
struct BoundaryLoop {
  std::vector<int> vertices;
  std::vector<int> faces;
  bool closed = true;  // false for a chain that ends at a non-manifold vertex
  double Perimeter(const geometry::Mesh& mesh) const;
};

// Boundary edges are edges with exactly one face.
std::vector<BoundaryLoop> BoundaryLoops(const geometry::Mesh& mesh);
std::vector<bool> BoundaryVertices(const geometry::Mesh& mesh);
// Per loop: whether it is the outer boundary of its piece of surface (faces connected through
// vertices), i.e. that piece's longest closed loop; the others are holes.
std::vector<bool> OuterLoops(const geometry::Mesh& mesh, const std::vector<BoundaryLoop>& loops);

// Sorted, unique neighbours of each vertex along face edges.
std::vector<std::vector<int>> VertexNeighbours(const geometry::Mesh& mesh);

// Area-weighted normals of the mesh's vertices (unnormalised sums of face cross products).
std::vector<Eigen::Vector3d> VertexNormals(const geometry::Mesh& mesh);

// Component id per face (faces sharing a vertex are connected), numbered 0.. in order of each
// component's first face; *count receives the number of components.
std::vector<int> FaceComponents(const geometry::Mesh& mesh, int* count);

// Keeps the faces with keep[f] (and their face_labels); vertices are not renumbered.
void KeepFaces(geometry::Mesh& mesh, const std::vector<bool>& keep);
// Drops vertices no face uses, renumbering faces (attributes follow). Returns the old index of
// each kept vertex.
std::vector<int> RemoveUnusedVertices(geometry::Mesh& mesh);

// Triangle quality 4 sqrt(3) area / sum of squared edges: 1 equilateral, 0 degenerate.
double TriangleQuality(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                       const Eigen::Vector3f& c);

// Undirected edge key of vertices a and b.
inline uint64_t EdgeKey(int a, int b) {
  const uint64_t lo = static_cast<uint32_t>(a < b ? a : b);
  const uint64_t hi = static_cast<uint32_t>(a < b ? b : a);
  return (hi << 32) | lo;
}
// Directed half-edge key a -> b.
inline uint64_t HalfEdgeKey(int a, int b) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

}  // namespace avc::surface
