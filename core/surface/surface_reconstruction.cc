#include "core/surface/surface_reconstruction.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/cluster/data_scale.h"
#include "core/cluster/point_grid.h"
#include "core/surface/boundary_growth.h"
#include "core/surface/cell_islands.h"
#include "core/surface/cluster_pieces.h"
#include "core/surface/hole_filling.h"
#include "core/surface/image_growth.h"
#include "core/surface/laplacian_smoothing.h"
#include "core/surface/mesh_topology.h"
#include "core/surface/triangulate_cell.h"
#include "core/util/validation.h"

namespace avc::surface {
namespace {

// The usable points, flattened, with the cell each belongs to (-1 for none yet).
struct UsablePoints {
  std::vector<Eigen::Vector3f> positions;
  std::vector<uint32_t> input_index;
  std::vector<int> cell;
};

UsablePoints Flatten(const ClusteredPoints& input, const ClusterMembers& members) {
  UsablePoints usable;
  for (const std::vector<uint32_t>& group : members.points) {
    for (uint32_t i : group) {
      usable.positions.push_back(input.cloud.positions[i]);
      usable.input_index.push_back(i);
    }
  }
  usable.cell.assign(usable.positions.size(), -1);
  return usable;
}

// Spacing and noise in force: given, or measured on the usable points. False (with a warning)
// when the spacing cannot be measured.
bool MeasureScales(const UsablePoints& usable, const SurfaceOptions& options, double* spacing,
                   double* noise, std::vector<std::string>* warnings) {
  *spacing = options.spacing;
  *noise = options.noise;
  if (*spacing > 0.0 && *noise >= 0.0) return true;
  try {
    const cluster::DataScale scale = cluster::EstimateDataScale(usable.positions);
    if (!(*spacing > 0.0)) *spacing = scale.spacing;
    if (*noise < 0.0) *noise = scale.noise;
    return true;
  } catch (const std::invalid_argument& error) {
    if (*spacing > 0.0) {
      *noise = 0.0;
      return true;
    }
    warnings->push_back(fmt::format(
        "surface: cannot measure the point spacing ({}); no surface made", error.what()));
    return false;
  }
}

// Two points lie on one local surface when their offset rises off the tangent planes by at most
// the link slope plus this many noise sigmas: the pieces of a cluster (Phase 1) and, when asked,
// the stitches between clusters (Phase 4).
constexpr double kSameSurfaceNoiseAllowance = 3.0;

// Phase 1: every cluster, piece by piece, into cells. Marks each usable point's cell.
std::vector<Cell> TriangulateClusters(const ClusteredPoints& input, const ClusterMembers& members,
                                      const SurfaceThresholds& thresholds, UsablePoints* usable,
                                      SurfaceReport* report) {
  std::vector<Cell> cells;
  std::vector<int> cell_of_input(input.cloud.size(), -1);
  for (size_t c = 0; c < members.ids.size(); ++c) {
    const std::vector<uint32_t>& group = members.points[c];
    const auto pieces = SplitIntoPieces(input, group, thresholds.piece_link,
                                        kSameSurfaceNoiseAllowance * thresholds.noise);
    std::string problem;
    size_t made = 0;
    for (const std::vector<uint32_t>& piece : pieces) {
      std::string piece_problem;
      std::vector<Cell> piece_cells =
          TriangulateSurfacePiece(input, members.ids[c], piece, thresholds.alpha, &piece_problem);
      if (piece_cells.empty()) {
        report->points_left_out += piece.size();
        if (problem.empty() || piece.size() >= 3) problem = piece_problem;
        continue;
      }
      for (Cell& cell : piece_cells) {
        for (int32_t i : cell.source_points) cell_of_input[i] = static_cast<int>(cells.size());
        report->phase1_faces += cell.mesh.faces.size();
        cells.push_back(std::move(cell));
        ++made;
      }
    }
    if (made == 0) {
      report->warnings.push_back(fmt::format("cluster {} ({} points): {}; its points are left out",
                                             members.ids[c], group.size(), problem));
    }
  }
  for (size_t k = 0; k < usable->positions.size(); ++k) {
    usable->cell[k] = cell_of_input[usable->input_index[k]];
  }
  return cells;
}

// Phase 2 without images: outlines away from other cells grow by the sampling's edge band.
void GrowCellsByBand(std::vector<Cell>& cells, const UsablePoints& usable,
                     SurfaceThresholds& thresholds, double growth_scale, SurfaceReport* report) {
  thresholds.growth_band = EstimateBoundaryBand(cells, thresholds.spacing, growth_scale);
  if (!(thresholds.growth_band > 0.0)) return;
  const float reach = static_cast<float>(thresholds.growth_clearance);
  const cluster::PointGrid grid(usable.positions, reach);
  for (size_t c = 0; c < cells.size(); ++c) {
    Cell& cell = cells[c];
    const auto is_free = [&](int vertex) {
      bool near_other = false;
      grid.ForEachWithin(cell.mesh.vertices[vertex], reach, [&](uint32_t j) {
        if (usable.cell[j] != static_cast<int>(c)) near_other = true;
      });
      return !near_other;
    };
    const GrowthStats stats = GrowOuterBoundary(cell, thresholds.growth_band, is_free);
    report->grown_vertices += stats.vertices;
  }
}

// A grid node belongs to another cell when one of its samples is within the growth clearance,
// or when the nearest sample within this many clearances is another cell's.
constexpr double kClaimRadiusFactor = 2.0;

// Phase 2 with images (image_growth.h): each cell grows as a level set over its plane where
// the masks see plant, stopping at background, at its neighbours and after the growth limit.
void GrowCellsWithImages(std::vector<Cell>& cells, const ClusteredPoints& input,
                         const UsablePoints& usable, const SurfaceImages& images,
                         const SurfaceOptions& options, const SurfaceThresholds& thresholds,
                         SurfaceReport* report) {
  const ImageEvidence evidence(images, options.image_growth);
  report->image_views = evidence.views();
  const float clearance = static_cast<float>(thresholds.growth_clearance);
  const float claim_radius = static_cast<float>(kClaimRadiusFactor) * clearance;
  const cluster::PointGrid grid(usable.positions, clearance);
  for (size_t c = 0; c < cells.size(); ++c) {
    const auto claimed_elsewhere = [&](const Eigen::Vector3d& point) {
      float own = std::numeric_limits<float>::infinity();
      float other = own;
      const Eigen::Vector3f p = point.cast<float>();
      grid.ForEachWithin(p, claim_radius, [&](uint32_t j) {
        const float d = (usable.positions[j] - p).squaredNorm();
        float& nearest = usable.cell[j] == static_cast<int>(c) ? own : other;
        nearest = std::min(nearest, d);
      });
      return other <= clearance * clearance || other < own;
    };
    const ImageGrowthStats stats =
        GrowCellWithImages(cells[c], input.cloud.positions, evidence, claimed_elsewhere,
                           thresholds.spacing, thresholds.alpha, options.fit, options.image_growth);
    report->image_growth += stats;
    report->grown_vertices += stats.vertices_added;
  }
}

size_t RemoveSmallComponents(geometry::Mesh& mesh, int min_faces) {
  int count = 0;
  const std::vector<int> component = FaceComponents(mesh, &count);
  std::vector<int> size(count, 0);
  for (int c : component) ++size[c];
  std::vector<bool> keep(mesh.faces.size(), true);
  size_t removed = 0;
  for (int c = 0; c < count; ++c) removed += size[c] < min_faces ? 1 : 0;
  for (size_t f = 0; f < keep.size(); ++f) keep[f] = size[component[f]] >= min_faces;
  if (removed > 0) KeepFaces(mesh, keep);
  return removed;
}

// Phase 4: cells stitched into one mesh, junction holes filled, final smoothing.
geometry::Mesh MergeCells(const std::vector<Cell>& cells, const SurfaceOptions& options,
                          const SurfaceThresholds& thresholds, SurfaceReport* report) {
  std::vector<int> vertex_cell;
  geometry::Mesh mesh = JoinCells(cells, &vertex_cell);
  std::vector<Eigen::Vector3d> normals;
  std::vector<int32_t> labels;
  for (const Cell& cell : cells) {
    normals.push_back(cell.plane.normal);
    labels.push_back(cell.cluster);
  }
  StitchRule rule;
  rule.distance = thresholds.stitch_distance;
  rule.own_cluster_distance = thresholds.own_cluster_stitch_distance;
  rule.max_tilt_deg = options.max_stitch_tilt_deg;
  rule.clear_of_other_cells = options.stitch_clear_of_other_cells;
  if (options.stitch_link_mean_slope >= 0.0) {
    rule.link_mean_slope = static_cast<float>(options.stitch_link_mean_slope);
    rule.link_allowance = static_cast<float>(kSameSurfaceNoiseAllowance * thresholds.noise);
  } else {
    rule.link_slope = -1.0f;
  }
  report->stitching = StitchCells(mesh, vertex_cell, normals, labels, rule);
  report->area_stitched = geometry::SurfaceArea(mesh);
  report->merged_holes_filled = FillSmallHoles(mesh, thresholds.hole_perimeter);
  SmoothSheet(mesh, options.final_smoothing);
  report->fragments_removed = RemoveSmallComponents(mesh, options.min_component_faces);
  RemoveUnusedVertices(mesh);
  return mesh;
}

}  // namespace

SurfaceResult ReconstructSurface(const ClusteredPoints& input, const SurfaceOptions& options,
                                 const SurfaceImages* images) {
  RequireValid(options);
  SurfaceResult result;
  SurfaceReport& report = result.report;
  report.input_points = input.cloud.size();
  const ClusterMembers members = GroupByCluster(input, &report.warnings);
  report.clusters = members.ids.size();
  UsablePoints usable = Flatten(input, members);
  report.used_points = usable.positions.size();

  double spacing = 0.0;
  double noise = 0.0;
  if (!MeasureScales(usable, options, &spacing, &noise, &report.warnings)) return result;
  SurfaceThresholds thresholds = ResolveThresholds(options, spacing, noise);

  const auto total_area = [](const std::vector<Cell>& all) {
    double area = 0.0;
    for (const Cell& cell : all) area += geometry::SurfaceArea(cell.mesh);
    return area;
  };
  std::vector<Cell> cells = TriangulateClusters(input, members, thresholds, &usable, &report);
  report.area_triangulated = total_area(cells);
  const bool images_asked = images != nullptr && options.image_growth.enabled;
  // Phase 3 refines what Phase 2 grew with the fit that grew it: with the ordinary one, vertices
  // 2-4 spacings beyond the samples were pulled back onto a strip's tilted quadric (a noisy
  // cylinder: 112 faces turned over, none with it; image_growth_test.cc).
  FittedSurfaceOptions refine_fit = options.fit;
  if (options.grow_boundary && images_asked && !images->views.empty()) {
    GrowCellsWithImages(cells, input, usable, *images, options, thresholds, &report);
    refine_fit = GrownPartFit(options.fit, options.image_growth);
  } else if (options.grow_boundary) {
    if (images_asked) {
      report.warnings.push_back(
          "surface: no views with plant masks for Phase 2's level sets; the outlines grow by "
          "the sampling's band instead");
    }
    GrowCellsByBand(cells, usable, thresholds, options.growth_scale, &report);
  }
  report.area_grown = total_area(cells);
  for (Cell& cell : cells) {
    report.modifications += ModifyCellMesh(cell.mesh, options, thresholds);
    cell.source_points.resize(cell.mesh.vertices.size(), -1);
    if (options.refine) {
      report.refinement +=
          RefineCell(cell, input.cloud.positions, spacing, options.refine_subdivisions, refine_fit);
    }
  }
  report.area_modified = total_area(cells);
  std::erase_if(cells, [](const Cell& cell) { return cell.mesh.faces.empty(); });
  cells = SplitCellsIntoPieces(std::move(cells), &report.cell_islands);
  report.cells = cells.size();
  report.thresholds = thresholds;

  result.mesh = MergeCells(cells, options, thresholds, &report);
  report.vertices = result.mesh.vertices.size();
  report.faces = result.mesh.faces.size();
  report.area = geometry::SurfaceArea(result.mesh);
  FaceComponents(result.mesh, &report.components);
  return result;
}

}  // namespace avc::surface
