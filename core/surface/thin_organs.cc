#include "core/surface/thin_organs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "core/surface/laplacian_smoothing.h"
#include "core/surface/mesh_topology.h"
#include "core/util/validation.h"

namespace avc::surface {
namespace {

using VoxelIndex = std::array<int, 3>;

VoxelIndex CellOf(const Eigen::Vector3f& point, double voxel_size) {
  return {static_cast<int>(std::floor(point.x() / voxel_size)),
          static_cast<int>(std::floor(point.y() / voxel_size)),
          static_cast<int>(std::floor(point.z() / voxel_size))};
}

VoxelIndex Shifted(const VoxelIndex& cell, int dx, int dy, int dz) {
  return {cell[0] + dx, cell[1] + dy, cell[2] + dz};
}

std::set<VoxelIndex> ToCells(const std::vector<Eigen::Vector3i>& voxels) {
  std::set<VoxelIndex> cells;
  for (const Eigen::Vector3i& v : voxels) cells.insert({v.x(), v.y(), v.z()});
  return cells;
}

// Steps (6-connected) from each occupied voxel to empty space: 1 on the proxy's boundary.
std::map<VoxelIndex, int> Depths(const std::set<VoxelIndex>& occupied) {
  std::map<VoxelIndex, int> depth;
  std::deque<VoxelIndex> queue;
  const std::array<VoxelIndex, 6> steps = {VoxelIndex{1, 0, 0}, VoxelIndex{-1, 0, 0},
                                           VoxelIndex{0, 1, 0}, VoxelIndex{0, -1, 0},
                                           VoxelIndex{0, 0, 1}, VoxelIndex{0, 0, -1}};
  for (const VoxelIndex& cell : occupied) {
    for (const VoxelIndex& s : steps) {
      if (!occupied.contains(Shifted(cell, s[0], s[1], s[2]))) {
        depth[cell] = 1;
        queue.push_back(cell);
        break;
      }
    }
  }
  while (!queue.empty()) {
    const VoxelIndex cell = queue.front();
    queue.pop_front();
    for (const VoxelIndex& s : steps) {
      const VoxelIndex next = Shifted(cell, s[0], s[1], s[2]);
      if (occupied.contains(next) && !depth.contains(next)) {
        depth[next] = depth[cell] + 1;
        queue.push_back(next);
      }
    }
  }
  return depth;
}

}  // namespace

std::string ThinOrganOptions::Validate() const {
  FirstProblem problem;
  const auto require = [&problem](bool ok, const std::string& what) {
    problem.Require(ok, "ThinOrganOptions." + what);
  };
  require(core_depth >= 1, "core_depth must be at least 1");
  require(core_reach >= 0, "core_reach must not be negative");
  require(std::isfinite(inward_voxels) && inward_voxels >= 0 && inward_voxels < 1,
          "inward_voxels must be in [0, 1)");
  require(smoothing_iterations >= 0, "smoothing_iterations must not be negative");
  return problem.text();
}

std::vector<Eigen::Vector3i> ThinVoxels(const std::vector<Eigen::Vector3f>& occupied_centres,
                                        double voxel_size, const ThinOrganOptions& options) {
  RequireValid(options);
  if (!(voxel_size > 0)) throw std::invalid_argument("ThinVoxels: voxel size must be positive");
  std::set<VoxelIndex> occupied;
  for (const Eigen::Vector3f& centre : occupied_centres)
    occupied.insert(CellOf(centre, voxel_size));
  // Everything within core_reach of a core voxel is bulky.
  std::set<VoxelIndex> bulky;
  for (const auto& [cell, depth] : Depths(occupied)) {
    if (depth < options.core_depth) continue;
    const int r = options.core_reach;
    for (int dz = -r; dz <= r; ++dz) {
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) bulky.insert(Shifted(cell, dx, dy, dz));
      }
    }
  }
  std::vector<Eigen::Vector3i> thin;
  for (const VoxelIndex& cell : occupied) {
    if (!bulky.contains(cell)) thin.emplace_back(cell[0], cell[1], cell[2]);
  }
  return thin;
}

geometry::Mesh VoxelSurface(const std::vector<Eigen::Vector3i>& voxels,
                            const std::vector<Eigen::Vector3i>& occupied, double voxel_size,
                            int smoothing_iterations, double inward_voxels) {
  const std::set<VoxelIndex> filled = ToCells(occupied);
  geometry::Mesh mesh;
  std::map<VoxelIndex, int> corner_index;
  const auto corner = [&](const VoxelIndex& c) {
    const auto [it, added] = corner_index.try_emplace(c, static_cast<int>(mesh.vertices.size()));
    if (added) {
      mesh.vertices.push_back((voxel_size * Eigen::Vector3d(c[0], c[1], c[2])).cast<float>());
    }
    return it->second;
  };
  for (const VoxelIndex& cell : ToCells(voxels)) {
    for (int axis = 0; axis < 3; ++axis) {
      // (a, b) with a x b = +axis: the quad base, +a, +a+b, +b winds counter-clockwise seen
      // from the +axis side.
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      for (int side : {0, 1}) {
        VoxelIndex neighbour = cell;
        neighbour[axis] += side == 1 ? 1 : -1;
        if (filled.contains(neighbour)) continue;
        VoxelIndex base = cell;
        base[axis] += side;
        VoxelIndex along_a = base, along_b = base, both = base;
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
  SmoothingOptions smoothing;
  smoothing.iterations = smoothing_iterations;
  if (smoothing_iterations > 0) SmoothSheet(mesh, smoothing);
  if (inward_voxels > 0) {
    const std::vector<Eigen::Vector3d> normals = VertexNormals(mesh);
    const double offset = inward_voxels * voxel_size;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      const double length = normals[v].norm();
      if (length > 0) mesh.vertices[v] -= (offset * normals[v] / length).cast<float>();
    }
  }
  return mesh;
}

size_t AddThinOrgans(geometry::Mesh& mesh, const std::vector<Eigen::Vector3f>& occupied_centres,
                     double voxel_size, const ThinOrganOptions& options, int32_t label) {
  const std::vector<Eigen::Vector3i> thin = ThinVoxels(occupied_centres, voxel_size, options);
  if (thin.empty()) return 0;
  std::vector<Eigen::Vector3i> occupied;
  for (const Eigen::Vector3f& centre : occupied_centres) {
    const VoxelIndex cell = CellOf(centre, voxel_size);
    occupied.emplace_back(cell[0], cell[1], cell[2]);
  }
  // Algorithm 3's faces in or next to the thin parts give way to their surface: its patches on
  // an organ one or two voxels wide stray up to a voxel off the proxy.
  std::set<VoxelIndex> thin_cells;
  for (const Eigen::Vector3i& v : thin) {
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) thin_cells.insert({v.x() + dx, v.y() + dy, v.z() + dz});
      }
    }
  }
  std::vector<bool> keep(mesh.faces.size(), true);
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& face = mesh.faces[f];
    const Eigen::Vector3f centroid =
        (mesh.vertices[face[0]] + mesh.vertices[face[1]] + mesh.vertices[face[2]]) / 3.0f;
    keep[f] = !thin_cells.contains(CellOf(centroid, voxel_size));
  }
  KeepFaces(mesh, keep);
  RemoveUnusedVertices(mesh);
  const geometry::Mesh tubes =
      VoxelSurface(thin, occupied, voxel_size, options.smoothing_iterations, options.inward_voxels);
  const int offset = static_cast<int>(mesh.vertices.size());
  const bool coloured = !mesh.colors.empty();
  for (const Eigen::Vector3f& vertex : tubes.vertices) {
    mesh.vertices.push_back(vertex);
    if (coloured) mesh.colors.push_back({128, 128, 128});
  }
  if (!mesh.uvs.empty()) mesh.uvs.resize(mesh.vertices.size(), Eigen::Vector2f::Zero());
  const bool labelled = !mesh.face_labels.empty() || mesh.faces.empty();
  for (const Eigen::Vector3i& face : tubes.faces) {
    mesh.faces.push_back(face.array() + offset);
    if (labelled) mesh.face_labels.push_back(label);
  }
  if (!mesh.face_materials.empty()) mesh.face_materials.resize(mesh.faces.size(), 0);
  return tubes.faces.size();
}

}  // namespace avc::surface
