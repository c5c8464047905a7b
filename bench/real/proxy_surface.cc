#include "bench/real/proxy_surface.h"

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "core/surface/laplacian_smoothing.h"
#include "core/surface/mesh_topology.h"

namespace avc::bench {
namespace {

using Cell = std::array<int, 3>;

}  // namespace

geometry::Mesh ProxyBoundaryMesh(const mvs::MvsBounds& proxy, int smoothing_iterations,
                                 double inward_voxels) {
  std::set<Cell> occupied;
  for (const Eigen::Vector3f& centre : proxy.occupied_centres) {
    occupied.insert({static_cast<int>(std::floor(centre.x() / proxy.voxel_size)),
                     static_cast<int>(std::floor(centre.y() / proxy.voxel_size)),
                     static_cast<int>(std::floor(centre.z() / proxy.voxel_size))});
  }
  geometry::Mesh mesh;
  std::map<Cell, int> corner_index;
  const auto corner = [&](const Cell& c) {
    const auto [it, added] = corner_index.try_emplace(c, static_cast<int>(mesh.vertices.size()));
    if (added) {
      mesh.vertices.push_back((proxy.voxel_size * Eigen::Vector3d(c[0], c[1], c[2])).cast<float>());
    }
    return it->second;
  };
  for (const Cell& cell : occupied) {
    for (int axis = 0; axis < 3; ++axis) {
      // (a, b) with a x b = +axis, so the quad a, a+b, b winds counter-clockwise seen from out.
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      for (int side : {0, 1}) {
        Cell neighbour = cell;
        neighbour[axis] += side == 1 ? 1 : -1;
        if (occupied.contains(neighbour)) continue;
        Cell base = cell;
        base[axis] += side;
        Cell along_a = base, along_b = base, both = base;
        along_a[a] += 1;
        along_b[b] += 1;
        both[a] += 1;
        both[b] += 1;
        std::array<int, 4> quad = {corner(base), corner(along_a), corner(both), corner(along_b)};
        if (side == 0) std::swap(quad[1], quad[3]);  // facing -axis
        mesh.faces.emplace_back(quad[0], quad[1], quad[2]);
        mesh.faces.emplace_back(quad[0], quad[2], quad[3]);
      }
    }
  }
  surface::SmoothingOptions smoothing;
  smoothing.iterations = smoothing_iterations;
  if (smoothing_iterations > 0) surface::SmoothInterior(mesh, smoothing);
  if (inward_voxels != 0) {
    const std::vector<Eigen::Vector3d> normals = surface::VertexNormals(mesh);
    const double offset = inward_voxels * proxy.voxel_size;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      const double length = normals[v].norm();
      if (length > 0) mesh.vertices[v] -= (offset * normals[v] / length).cast<float>();
    }
  }
  return mesh;
}

}  // namespace avc::bench
