#include "core/surface/triangle_cleanup.h"

#include <vector>

#include "core/surface/mesh_topology.h"

namespace avc::surface {

size_t RemoveLongTriangles(geometry::Mesh& mesh, double max_edge) {
  const float limit2 = static_cast<float>(max_edge * max_edge);
  std::vector<bool> keep(mesh.faces.size(), true);
  size_t removed = 0;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      if ((mesh.vertices[t[k]] - mesh.vertices[t[(k + 1) % 3]]).squaredNorm() > limit2) {
        keep[f] = false;
      }
    }
    if (!keep[f]) ++removed;
  }
  if (removed > 0) KeepFaces(mesh, keep);
  return removed;
}

size_t PeelBoundarySlivers(geometry::Mesh& mesh, double min_quality) {
  size_t removed = 0;
  while (true) {
    std::vector<bool> keep(mesh.faces.size(), true);
    size_t this_round = 0;
    for (const BoundaryLoop& loop : BoundaryLoops(mesh)) {
      for (int f : loop.faces) {
        if (!keep[f]) continue;
        const Eigen::Vector3i& t = mesh.faces[f];
        if (TriangleQuality(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]) <
            min_quality) {
          keep[f] = false;
          ++this_round;
        }
      }
    }
    if (this_round == 0) return removed;
    KeepFaces(mesh, keep);
    removed += this_round;
  }
}

}  // namespace avc::surface
