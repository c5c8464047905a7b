#include "services/surfacer/surfacer_options.h"

#include <stdexcept>
#include <string>

namespace avc::surfacer {
namespace {

using config::OptionTable;
using Table = OptionTable<SurfacerOptions>;

void AddThinOrgans(Table& table) {
  table
      .Add("thin_organs.enabled", [](auto& o) -> auto& { return o.thin_organs.enabled; },
           {"", "surface the proxy's thin parts (stems, siliques; not for broad leaves) from it"})
      .Add("thin_organs.core_depth", [](auto& o) -> auto& { return o.thin_organs.core_depth; },
           {"voxels", "a voxel this deep inside the proxy is part of a bulky core", 1, 1000})
      .Add("thin_organs.core_reach", [](auto& o) -> auto& { return o.thin_organs.core_reach; },
           {"voxels", "thin parts lie farther than this from any core", 0, 1000})
      .Add("thin_organs.inward_voxels",
           [](auto& o) -> auto& { return o.thin_organs.inward_voxels; },
           {"voxels", "the thin parts' surface is moved this far in (the hull's margin)", 0, 0.99})
      .Add("thin_organs.smoothing_iterations",
           [](auto& o) -> auto& { return o.thin_organs.smoothing_iterations; },
           {"pairs", "Taubin pairs smoothing the thin parts' voxel surface", 0, 1000});
}

void AddScales(Table& table) {
  table
      .Add("surface.spacing", [](auto& o) -> auto& { return o.surface.spacing; },
           {"m", "point spacing every threshold is a multiple of (0: measured)", 0, 1})
      .Add("surface.noise", [](auto& o) -> auto& { return o.surface.noise; },
           {"m", "point noise across the surface (< 0: measured)", -1, 1})
      .Add("surface.piece_link_factor",
           [](auto& o) -> auto& { return o.surface.piece_link_factor; },
           {"spacings", "a cluster is triangulated in pieces linked closer than this", 0.1, 100})
      .Add("surface.alpha_factor", [](auto& o) -> auto& { return o.surface.alpha_factor; },
           {"spacings", "Phase 1 alpha: larger fills more concavities, keeps more slivers", 0.1,
            100});
}

void AddGrowth(Table& table) {
  table
      .Add("surface.grow_boundary", [](auto& o) -> auto& { return o.surface.grow_boundary; },
           {"", "Phase 2: grow the cells' outlines"})
      .Add("surface.growth_scale", [](auto& o) -> auto& { return o.surface.growth_scale; },
           {"", "band growth without images, times the sampling's band (0: chosen)", 0, 100})
      .Add("surface.growth_clearance_factor",
           [](auto& o) -> auto& { return o.surface.growth_clearance_factor; },
           {"spacings", "an outline this close to another cell does not grow", 0, 100})
      .Add("surface.image_growth.enabled",
           [](auto& o) -> auto& { return o.surface.image_growth.enabled; },
           {"", "grow over the plant masks when the views are given"})
      .Add("surface.image_growth.max_growth_factor",
           [](auto& o) -> auto& { return o.surface.image_growth.max_growth_factor; },
           {"spacings", "farthest an outline may grow: further closes bigger gaps, guesses more", 0,
            1000})
      .Add("surface.image_growth.grid_factor",
           [](auto& o) -> auto& { return o.surface.image_growth.grid_factor; },
           {"spacings", "grid pitch the grown outline is placed to", 0.01, 100})
      .Add("surface.image_growth.min_plant_views",
           [](auto& o) -> auto& { return o.surface.image_growth.min_plant_views; },
           {"views", "views that must see plant at a grid node", 1, 1000})
      .Add("surface.image_growth.min_background_views",
           [](auto& o) -> auto& { return o.surface.image_growth.min_background_views; },
           {"views", "views seeing background that rule a node out", 1, 1000})
      .Add("surface.image_growth.edge_tolerance_px",
           [](auto& o) -> auto& { return o.surface.image_growth.edge_tolerance_px; },
           {"px", "mask pixels count as background only this far from plant", 0, 100})
      .Add("surface.image_growth.smoothing_factor",
           [](auto& o) -> auto& { return o.surface.image_growth.smoothing_factor; },
           {"spacings", "curvature smoothing of the grown region", 0, 100})
      .Add("surface.image_growth.colour_agreement",
           [](auto& o) -> auto& { return o.surface.image_growth.colour_agreement; },
           {"", "a node's colours must agree with its cell's colour model"})
      .Add("surface.image_growth.colour.tolerance_factor",
           [](auto& o) -> auto& { return o.surface.image_growth.colour.tolerance_factor; },
           {"", "colour tolerance in RMS chromaticity distances of the cell's points", 0, 100})
      .Add("surface.image_growth.colour.min_tolerance",
           [](auto& o) -> auto& { return o.surface.image_growth.colour.min_tolerance; },
           {"", "smallest chromaticity tolerance", 0, 1})
      .Add("surface.image_growth.colour.min_colours",
           [](auto& o) -> auto& { return o.surface.image_growth.colour.min_colours; },
           {"", "fewer usable colours: no colour model", 1, 1000000});
}

void AddSmoothing(Table& table, const std::string& name, auto smoothing) {
  table
      .Add(name + ".iterations", [smoothing](auto& o) -> auto& { return smoothing(o).iterations; },
           {"", "lambda|mu smoothing pairs", 0, 1000})
      .Add(name + ".lambda", [smoothing](auto& o) -> auto& { return smoothing(o).lambda; },
           {"", "shrinking step", 0, 1})
      .Add(name + ".mu", [smoothing](auto& o) -> auto& { return smoothing(o).mu; },
           {"", "inflating step (below -lambda)", -1, 0});
}

void AddModifications(Table& table) {
  AddSmoothing(
      table, "surface.cell_smoothing", [](auto& o) -> auto& { return o.surface.cell_smoothing; });
  table
      .Add("surface.long_edge_factor", [](auto& o) -> auto& { return o.surface.long_edge_factor; },
           {"spacings", "faces with a longer edge are removed", 0.1, 1000})
      .Add("surface.min_boundary_quality",
           [](auto& o) -> auto& { return o.surface.min_boundary_quality; },
           {"", "boundary faces of lower quality (1 equilateral) are peeled off", 0, 1})
      .Add("surface.hole_perimeter_factor",
           [](auto& o) -> auto& { return o.surface.hole_perimeter_factor; },
           {"spacings", "holes up to this perimeter are filled", 0, 10000})
      .Add("surface.refine", [](auto& o) -> auto& { return o.surface.refine; },
           {"", "move vertices onto the surface fitted to each cell's points"})
      .Add("surface.refine_subdivisions",
           [](auto& o) -> auto& { return o.surface.refine_subdivisions; },
           {"", "1-to-4 subdivisions before refinement", 0, 3})
      .Add("surface.fit.radius_factor",
           [](auto& o) -> auto& { return o.surface.fit.radius_factor; },
           {"spacings", "fitted surface neighbourhood radius", 0.1, 100})
      .Add("surface.fit.max_radius_factor",
           [](auto& o) -> auto& { return o.surface.fit.max_radius_factor; },
           {"spacings", "... widened up to this", 0.1, 100})
      .Add("surface.fit.min_points", [](auto& o) -> auto& { return o.surface.fit.min_points; },
           {"points", "points a fitted neighbourhood needs", 3, 10000});
}

void AddMerging(Table& table) {
  table
      .Add("surface.stitch_factor", [](auto& o) -> auto& { return o.surface.stitch_factor; },
           {"spacings",
            "Phase 4 stitches cells of different clusters this close: more joins "
            "leaf pieces and bridges neighbouring leaves",
            0, 100})
      .Add("surface.own_cluster_stitch_factor",
           [](auto& o) -> auto& { return o.surface.own_cluster_stitch_factor; },
           {"spacings", "... and cells of one cluster (0: stitch_factor)", 0, 100})
      .Add("surface.max_stitch_tilt_deg",
           [](auto& o) -> auto& { return o.surface.max_stitch_tilt_deg; },
           {"deg", "a stitch faces within this of its cells' mean normal", 0, 180})
      .Add("surface.stitch_link_mean_slope",
           [](auto& o) -> auto& { return o.surface.stitch_link_mean_slope; },
           {"", "stitch different clusters only along one surface (< 0: off)", -1, 1})
      .Add("surface.stitch_clear_of_other_cells",
           [](auto& o) -> auto& { return o.surface.stitch_clear_of_other_cells; },
           {"", "refuse stitches passing over a third cell"});
  AddSmoothing(
      table, "surface.final_smoothing", [](auto& o) -> auto& { return o.surface.final_smoothing; });
  table.Add("surface.min_component_faces",
            [](auto& o) -> auto& { return o.surface.min_component_faces; },
            {"faces", "smaller connected pieces are dropped at the end", 0, 1000000});
}

Table MakeTable() {
  Table table("surfacer", [](const SurfacerOptions& options) { return options.Validate(); });
  AddScales(table);
  AddGrowth(table);
  AddModifications(table);
  AddMerging(table);
  AddThinOrgans(table);
  return table;
}

}  // namespace

const config::OptionTable<SurfacerOptions>& SurfacerOptionTable() {
  static const Table table = MakeTable();
  return table;
}

}  // namespace avc::surfacer
