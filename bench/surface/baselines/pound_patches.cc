#include "bench/surface/baselines/pound_patches.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "bench/surface/baselines/baseline_input.h"
#include "core/cluster/point_grid.h"
#include "core/surface/boundary_growth.h"
#include "core/surface/clustered_points.h"
#include "core/surface/triangulate_cell.h"

namespace avc::surface::baselines {
namespace {

constexpr const char* kPoundPatches = "Pound patches baseline";

// A planar section: every vertex moved onto the patch's regression plane.
void Flatten(Cell& cell) {
  for (Eigen::Vector3f& vertex : cell.mesh.vertices) {
    const Eigen::Vector2d q = cell.plane.Project(vertex);
    vertex = (cell.plane.origin + q.x() * cell.plane.u + q.y() * cell.plane.v).cast<float>();
  }
}

}  // namespace

std::vector<int32_t> FixedRadiusPatches(const std::vector<Eigen::Vector3f>& points, double radius) {
  const float reach = static_cast<float>(radius);
  const cluster::PointGrid grid(points, reach);
  std::vector<int32_t> patch(points.size(), -1);
  int32_t next = 0;
  for (size_t seed = 0; seed < points.size(); ++seed) {
    if (patch[seed] >= 0) continue;
    grid.ForEachWithin(points[seed], reach, [&](uint32_t j) {
      if (patch[j] < 0) patch[j] = next;
    });
    ++next;
  }
  return patch;
}

geometry::Mesh PoundPatches(const geometry::PointCloud& cloud, const PoundOptions& options) {
  CheckBaselineInput(cloud, kPoundPatches, /*require_normals=*/false);
  if (!(options.patch_radius_factor > 0.0) || !(options.alpha_factor > 0.0) ||
      !(options.growth_clearance_factor >= 0.0)) {
    throw std::invalid_argument(fmt::format(
        "{}: patch_radius_factor and alpha_factor must be > 0, growth_clearance_factor >= 0",
        kPoundPatches));
  }
  const double spacing = ResolveSpacing(cloud, options.spacing, kPoundPatches);
  ClusteredPoints input;
  input.cloud = cloud;
  input.clusters = FixedRadiusPatches(cloud.positions, options.patch_radius_factor * spacing);
  std::vector<std::string> ignored;
  const ClusterMembers members = GroupByCluster(input, &ignored);

  std::vector<Cell> cells;
  for (size_t c = 0; c < members.ids.size(); ++c) {
    std::string problem;  // a patch that cannot be triangulated is simply missing
    Cell cell = TriangulateCell(input, members.ids[c], members.points[c],
                                options.alpha_factor * spacing, &problem);
    if (cell.mesh.faces.empty()) continue;
    Flatten(cell);
    cells.push_back(std::move(cell));
  }

  // Planar growth of every outline that no other patch is near (Pound's level sets stop at
  // neighbouring surfaces), by the same band the surfacer's Phase 2 stand-in uses.
  const double band = EstimateBoundaryBand(cells, spacing, 0.0);
  const float clearance = static_cast<float>(options.growth_clearance_factor * spacing);
  const cluster::PointGrid grid(cloud.positions, std::max(clearance, static_cast<float>(spacing)));
  geometry::Mesh mesh;
  for (Cell& cell : cells) {
    if (band > 0.0) {
      const auto is_free = [&](int vertex) {
        bool near_other = false;
        grid.ForEachWithin(cell.mesh.vertices[vertex], clearance, [&](uint32_t j) {
          if (input.clusters[j] != cell.cluster) near_other = true;
        });
        return !near_other;
      };
      GrowOuterBoundary(cell, band, is_free);
    }
    mesh.Append(cell.mesh);
  }
  return mesh;
}

}  // namespace avc::surface::baselines
