#include "bench/surface/baselines/trim_to_data.h"

#include "core/cluster/point_grid.h"
#include "core/surface/mesh_topology.h"

namespace avc::surface::baselines {

size_t TrimToData(geometry::Mesh& mesh, const std::vector<Eigen::Vector3f>& points,
                  double max_distance) {
  const float reach = static_cast<float>(max_distance);
  const cluster::PointGrid grid(points, reach);
  std::vector<bool> keep(mesh.faces.size(), false);
  size_t removed = 0;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    const Eigen::Vector3f centroid =
        (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0f;
    bool near = false;
    grid.ForEachWithin(centroid, reach, [&](uint32_t) { near = true; });
    keep[f] = near;
    removed += near ? 0 : 1;
  }
  KeepFaces(mesh, keep);
  RemoveUnusedVertices(mesh);
  return removed;
}

}  // namespace avc::surface::baselines
