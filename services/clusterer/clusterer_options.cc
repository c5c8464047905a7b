#include "services/clusterer/clusterer_options.h"

namespace avc::clusterer {
namespace {

using config::OptionTable;

void AddScales(OptionTable<ClustererOptions>& table) {
  table
      .Add("merge.min_points", [](auto& o) -> auto& { return o.merge.min_points; },
           {"points",
            "MVS points a proxy voxel needs to become a merged point (paper: more than "
            "3); fewer keeps thin organs and more noise",
            1, 1000})
      .Add("cluster.spacing", [](auto& o) -> auto& { return o.cluster.spacing; },
           {"m",
            "merged point spacing every threshold is a multiple of (0: the median "
            "nearest-neighbour distance)",
            0, 1})
      .Add("cluster.noise", [](auto& o) -> auto& { return o.cluster.noise; },
           {"m", "point noise (0: the median local plane residual)", 0, 1})
      .Add("cluster.link_factor", [](auto& o) -> auto& { return o.cluster.link_factor; },
           {"spacings", "points closer than this are neighbours: larger bridges gaps and leaves", 1,
            100})
      .Add("cluster.link_slope", [](auto& o) -> auto& { return o.cluster.link_slope; },
           {"", "neighbours' offset rises at most asin(this) above both tangent planes", 0, 1})
      .Add("cluster.link_mean_slope", [](auto& o) -> auto& { return o.cluster.link_mean_slope; },
           {"", "... and above the plane normal to their normals' bisector (< 0: no test)", -1, 1})
      .Add("cluster.bin_factor", [](auto& o) -> auto& { return o.cluster.bin_factor; },
           {"spacings", "bin width of the normal split", 0.01, 100})
      .Add("cluster.noise_factor", [](auto& o) -> auto& { return o.cluster.noise_factor; },
           {"", "a cluster is flat when its thickness is at most this many noises", 0, 100})
      .Add("cluster.flatness_ratio", [](auto& o) -> auto& { return o.cluster.flatness_ratio; },
           {"", "... or its thickness over its width at most this", 0, 1})
      .Add("cluster.min_normal_gain", [](auto& o) -> auto& { return o.cluster.min_normal_gain; },
           {"",
            "a normal split must raise normal coherence by this fraction: lower splits bent "
            "leaves",
            0, 1})
      .Add("cluster.tube.min_alignment",
           [](auto& o) -> auto& { return o.cluster.tube.min_alignment; },
           {"", "a stem's normals point away from its axis at least this much (> 1: no stems)", 0,
            2})
      .Add("cluster.tube.max_radius_spread",
           [](auto& o) -> auto& { return o.cluster.tube.max_radius_spread; },
           {"", "a stem's distances to its axis vary at most this much over their mean", 0, 10});
}

void AddRounds(OptionTable<ClustererOptions>& table) {
  table
      .Add("cluster.refinement_rounds",
           [](auto& o) -> auto& { return o.cluster.refinement_rounds; },
           {"", "point-wise refinement passes after a split", 0, 100})
      .Add("cluster.min_cluster_points",
           [](auto& o) -> auto& { return o.cluster.min_cluster_points; },
           {"points", "smallest real cluster (0: 13, a disc two spacings across)", 0, 1000000})
      .Add("cluster.reassignment_rounds",
           [](auto& o) -> auto& { return o.cluster.reassignment_rounds; },
           {"", "passes of the outlier constraint", 0, 100});
}

void AddSplits(OptionTable<ClustererOptions>& table) {
  table
      .Add("cluster.neck_neighbours", [](auto& o) -> auto& { return o.cluster.neck_neighbours; },
           {"", "k of the neighbour graph a neck is cut on", 2, 1000})
      .Add("cluster.neck_lanczos_steps",
           [](auto& o) -> auto& { return o.cluster.neck_lanczos_steps; },
           {"", "Lanczos steps of the neck's spectral cut", 2, 10000})
      .Add("cluster.neck_bend_factor", [](auto& o) -> auto& { return o.cluster.neck_bend_factor; },
           {"", "normal-bend weighting of the neck graph (0: unweighted)", 0, 1000})
      .Add("cluster.max_neck_ratio", [](auto& o) -> auto& { return o.cluster.max_neck_ratio; },
           {"",
            "largest neck (contact over the narrower side's width) that is cut: higher cuts "
            "whole leaves",
            0, 10})
      .Add("cluster.neck_elevation_factor",
           [](auto& o) -> auto& { return o.cluster.neck_elevation_factor; },
           {"", "elevation weighting when a neck cut is redrawn (0: not redrawn)", 0, 1000})
      .Add(
          "cluster.neck_max_boundary_shift",
          [](auto& o) -> auto& { return o.cluster.neck_max_boundary_shift; },
          {"", "a redrawn neck is kept when at most this fraction of the smaller side moves", 0, 1})
      .Add("cluster.sheet_lanczos_steps",
           [](auto& o) -> auto& { return o.cluster.sheet_lanczos_steps; },
           {"", "Lanczos steps of the overlapping-sheet cut", 2, 10000})
      .Add(
          "cluster.sheet_smoothing_factor",
          [](auto& o) -> auto& { return o.cluster.sheet_smoothing_factor; },
          {"", "normals are smoothed over neighbours bent at most this many median bends", 0, 1000})
      .Add("cluster.sheet_bend_factor",
           [](auto& o) -> auto& { return o.cluster.sheet_bend_factor; },
           {"", "edge weights fall with bend over this many median bends", 0.001, 1000})
      .Add("cluster.max_sheet_edge_bias",
           [](auto& o) -> auto& { return o.cluster.max_sheet_edge_bias; },
           {"", "a sheet cut is kept when neither side ends at it by more than this", 0, 1});
}

OptionTable<ClustererOptions> MakeTable() {
  OptionTable<ClustererOptions> table(
      "clusterer", [](const ClustererOptions& options) { return options.Validate(); });
  AddScales(table);
  AddRounds(table);
  AddSplits(table);
  return table;
}

}  // namespace

const config::OptionTable<ClustererOptions>& ClustererOptionTable() {
  static const OptionTable<ClustererOptions> table = MakeTable();
  return table;
}

}  // namespace avc::clusterer
