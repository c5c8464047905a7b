#include "services/builder/builder_options.h"

#include <stdexcept>
#include <string>

#include "core/segmentation/mask_option_table.h"

namespace avc::builder {
namespace {

using config::OptionTable;

void AddMethods(OptionTable<ReconstructOptions>& table) {
  table.AddText(
      "method", [](const ReconstructOptions& o) { return MvsMethodName(o.method); },
      [](ReconstructOptions& o, std::string_view text) {
        o.method = ParseMvsMethod(std::string(text));
      },
      {"", "multi-view stereo: patch (PMVS-style, the paper's), plane-sweep or none"});
  // The automatic masks (core/segmentation/plant_mask.h says each option's trade-off).
  segmentation::AddMaskOptions(
      table, "masks", [](auto& o) -> auto& { return o.masks; });
}

void AddProxy(OptionTable<ReconstructOptions>& table) {
  table
      .Add("proxy.background_votes_allowed",
           [](auto& o) -> auto& { return o.proxy.background_votes_allowed; },
           {"views",
            "a voxel survives this many background votes: more keeps leaves a mask lost, "
            "and more air",
            0, 1000})
      .Add(
          "proxy.min_plant_views", [](auto& o) -> auto& { return o.proxy.min_plant_views; },
          {"views", "plant votes an occupied voxel needs (0: half the views, at least 2)", 0, 1000})
      .Add("proxy.final_voxel_size", [](auto& o) -> auto& { return o.proxy.final_voxel_size; },
           {"m", "voxel edge after the last resolution increase (0: longest box edge / 256)", 0, 1})
      .Add("proxy.resolution_increases",
           [](auto& o) -> auto& { return o.proxy.resolution_increases; },
           {"", "halvings of the voxel size from the first carving to the final", 0, 8})
      .Add("proxy.coarse_levels", [](auto& o) -> auto& { return o.proxy.coarse_levels; },
           {"", "octree levels above a voxel used to prune empty space (0: automatic)", 0, 16});
}

void AddPatch(OptionTable<ReconstructOptions>& table) {
  table
      .Add("patch.level", [](auto& o) -> auto& { return o.patch.level; },
           {"",
            "image pyramid level (-1: halve until the longer side is at most 1600 px); "
            "higher is faster and coarser",
            -1, 8})
      .Add("patch.cell_size", [](auto& o) -> auto& { return o.patch.cell_size; },
           {"px", "one patch per cell of this side: smaller gives denser points, slower", 1, 64})
      .Add("patch.window", [](auto& o) -> auto& { return o.patch.window; },
           {"px", "patch sampling grid side (odd); wider matches more reliably, fattens edges", 3,
            31})
      .Add("patch.ncc_threshold", [](auto& o) -> auto& { return o.patch.ncc_threshold; },
           {"",
            "NCC an image needs to support an optimised patch: higher is more precise, "
            "sparser",
            -1, 1})
      .Add("patch.ncc_threshold_before",
           [](auto& o) -> auto& { return o.patch.ncc_threshold_before; },
           {"", "the same before optimisation", -1, 1})
      .Add("patch.min_images", [](auto& o) -> auto& { return o.patch.min_images; },
           {"images", "images a patch needs (0: 3, or 4 with 24 views or more)", 0, 100})
      .Add("patch.max_view_angle", [](auto& o) -> auto& { return o.patch.max_view_angle; },
           {"rad", "largest angle between a patch's normal and the ray to a camera that sees it", 0,
            1.5708})
      .Add("patch.features_per_block", [](auto& o) -> auto& { return o.patch.features_per_block; },
           {"", "seed features kept per detector in each block", 1, 1000})
      .Add("patch.feature_block", [](auto& o) -> auto& { return o.patch.feature_block; },
           {"px", "side of the blocks features are spread over", 2, 4096})
      .Add("patch.epipolar_distance", [](auto& o) -> auto& { return o.patch.epipolar_distance; },
           {"px", "seed matches lie this close to the epipolar line", 0, 100})
      .Add("patch.max_seed_candidates",
           [](auto& o) -> auto& { return o.patch.max_seed_candidates; },
           {"", "triangulated candidates tried per feature", 1, 10000})
      .Add("patch.seed_neighbours", [](auto& o) -> auto& { return o.patch.seed_neighbours; },
           {"images", "images each image is matched against for seeds", 1, 1000})
      .Add("patch.rounds", [](auto& o) -> auto& { return o.patch.rounds; },
           {"", "expansion and filtering rounds: more fill more cells, slower", 0, 10})
      .Add("patch.max_iterations", [](auto& o) -> auto& { return o.patch.max_iterations; },
           {"", "Nelder-Mead iterations per patch", 1, 10000})
      .Add("patch.max_refine_images", [](auto& o) -> auto& { return o.patch.max_refine_images; },
           {"images", "images a patch is optimised against (best NCC first)", 1, 1000})
      .Add("patch.min_texture", [](auto& o) -> auto& { return o.patch.min_texture; },
           {"", "RGB standard deviation (0-255) below which a reference patch is refused", 0, 255})
      .Add("patch.occlusion_cells", [](auto& o) -> auto& { return o.patch.occlusion_cells; },
           {"cells", "depth by which another patch hides one", 0, 1000})
      .Add("patch.regularity_threshold",
           [](auto& o) -> auto& { return o.patch.regularity_threshold; },
           {"px",
            "largest distance from the plane of a patch's neighbours: lower is more "
            "precise, drops more points",
            0, 1000})
      .Add("patch.min_group_size", [](auto& o) -> auto& { return o.patch.min_group_size; },
           {"patches", "smaller connected groups of patches are dropped", 0, 1000000})
      .Add("patch.whole_patch_in_mask",
           [](auto& o) -> auto& { return o.patch.whole_patch_in_mask; },
           {"", "every corner of a patch on mask pixels: 1 on, 0 off, -1 from the image size", -1,
            1})
      .Add("patch.bounds_dilation", [](auto& o) -> auto& { return o.patch.bounds_dilation; },
           {"voxels", "patches lie this close to an occupied proxy voxel", 0, 100});
}

void AddSweep(OptionTable<ReconstructOptions>& table) {
  table
      .Add("sweep.level", [](auto& o) -> auto& { return o.sweep.level; },
           {"", "image pyramid level (-1: the longer side at most 800 px)", -1, 8})
      .Add("sweep.window", [](auto& o) -> auto& { return o.sweep.window; },
           {"px", "ZNCC window side (odd)", 3, 31})
      .Add("sweep.neighbours", [](auto& o) -> auto& { return o.sweep.neighbours; },
           {"views", "views swept against each reference", 1, 100})
      .Add("sweep.best_k", [](auto& o) -> auto& { return o.sweep.best_k; },
           {"views", "a depth scores the mean ZNCC of its best k neighbours", 1, 100})
      .Add("sweep.max_plane_step_px", [](auto& o) -> auto& { return o.sweep.max_plane_step_px; },
           {"px", "largest shift in a neighbour between two depth planes", 0.01, 100})
      .Add("sweep.max_planes", [](auto& o) -> auto& { return o.sweep.max_planes; },
           {"", "depth planes per reference at most", 2, 100000})
      .Add("sweep.depth_margin_voxels",
           [](auto& o) -> auto& { return o.sweep.depth_margin_voxels; },
           {"voxels", "the proxy's depth interval is widened by this on each side", 0, 100})
      .Add("sweep.min_texture_std", [](auto& o) -> auto& { return o.sweep.min_texture_std; },
           {"", "grey standard deviation (0-1) below which a window is untextured", 0, 1})
      .Add("sweep.min_score", [](auto& o) -> auto& { return o.sweep.min_score; },
           {"", "aggregated ZNCC a depth needs", -1, 1})
      .Add("sweep.consistency_tolerance",
           [](auto& o) -> auto& { return o.sweep.consistency_tolerance; },
           {"", "relative depth agreement between two views' depth maps", 0, 1})
      .Add("sweep.min_consistent_views",
           [](auto& o) -> auto& { return o.sweep.min_consistent_views; },
           {"views", "consistent views a pixel needs to become a point", 0, 100})
      .Add("sweep.cell_px", [](auto& o) -> auto& { return o.sweep.cell_px; },
           {"px", "fusion keeps the best point per cube of this many pixel footprints", 0.1, 100})
      .Add("sweep.normal_step_px", [](auto& o) -> auto& { return o.sweep.normal_step_px; },
           {"px", "depth-map normals from points this far apart", 1, 100});
}

void AddSoil(OptionTable<ReconstructOptions>& table) {
  table
      .Add("soil.enabled", [](auto& o) -> auto& { return o.soil.enabled; },
           {"", "search for the soil surface the plant's height is measured from"})
      .Add("soil.inner_radius", [](auto& o) -> auto& { return o.soil.inner_radius; },
           {"m", "soil is searched outside this distance from the stem", 0, 10})
      .Add("soil.outer_radius", [](auto& o) -> auto& { return o.soil.outer_radius; },
           {"m", "... and inside this one (inside the pot's rim)", 0, 10})
      .Add("soil.sample_spacing", [](auto& o) -> auto& { return o.soil.sample_spacing; },
           {"m", "between soil patch centres", 1e-5, 1})
      .Add("soil.search_below", [](auto& o) -> auto& { return o.soil.search_below; },
           {"m", "soil planes tried below the proxy's base", 0, 10})
      .Add("soil.search_above", [](auto& o) -> auto& { return o.soil.search_above; },
           {"m", "... and above it", 0, 10})
      .Add("soil.coarse_step", [](auto& o) -> auto& { return o.soil.coarse_step; },
           {"m", "between planes of the first sweep", 1e-6, 1})
      .Add("soil.fine_step", [](auto& o) -> auto& { return o.soil.fine_step; },
           {"m", "between planes of the second sweep", 1e-6, 1})
      .Add("soil.min_views", [](auto& o) -> auto& { return o.soil.min_views; },
           {"views", "views a soil patch needs", 2, 1000})
      .Add("soil.min_elevation_deg", [](auto& o) -> auto& { return o.soil.min_elevation_deg; },
           {"deg", "only views looking down at least this steeply count", 0, 90})
      .Add("soil.min_patches", [](auto& o) -> auto& { return o.soil.min_patches; },
           {"", "patches a plane needs", 1, 1000000})
      .Add("soil.max_contrast", [](auto& o) -> auto& { return o.soil.max_contrast; },
           {"",
            "the best plane's disagreement over the median plane's (0: never measure from "
            "soil)",
            0, 1});
}

void AddSupport(OptionTable<ReconstructOptions>& table) {
  table
      .Add("points.proxy_margin", [](auto& o) -> auto& { return o.points_proxy_margin; },
           {"voxels", "MVS points farther than this from the proxy leave points.ply (-1: keep all)",
            -1, 100})
      .Add("support.enabled", [](auto& o) -> auto& { return o.support.enabled; },
           {"", "find a support the masks took for plant and cut the proxy at its top"})
      .Add(
          "support.min_jump", [](auto& o) -> auto& { return o.support.min_jump; },
          {"", "the support's top slice holds this many times the plant's median slice", 1.01, 1e6})
      .Add("support.min_mass_fraction",
           [](auto& o) -> auto& { return o.support.min_mass_fraction; },
           {"", "the support and below hold at least this fraction of the proxy", 0, 1})
      .Add("support.min_plant_slices", [](auto& o) -> auto& { return o.support.min_plant_slices; },
           {"slices", "plant slices needed above a support", 1, 100000});
}

OptionTable<ReconstructOptions> MakeTable() {
  OptionTable<ReconstructOptions> table(
      "builder", [](const ReconstructOptions& options) { return options.Validate(); });
  AddMethods(table);
  AddProxy(table);
  AddPatch(table);
  AddSweep(table);
  AddSoil(table);
  AddSupport(table);
  return table;
}

}  // namespace

const config::OptionTable<ReconstructOptions>& BuilderOptionTable() {
  static const OptionTable<ReconstructOptions> table = MakeTable();
  return table;
}

}  // namespace avc::builder
