#pragma once

// The paper's hybrid clustering (Gibbs et al. §3.2, Algorithm 2) of a merged plant point cloud
// with normals into surface patches that can each be triangulated on their regression plane.
//
// Start: connected components of proximal points (within the link radius and on the same local
// surface; Algorithm 2 line 8, "patch"); components smaller than min_cluster_points are outliers.
// Loop over a work list until every cluster satisfies the constraints:
//  1. Normal constraint (normal_split.h): a cluster is flat when its RMS distance to the PCA plane,
//     sqrt(lambda_min), is within noise_factor * noise, or its flatness sqrt(lambda_min /
//     lambda_mid) is within flatness_ratio. Otherwise it is cut on the 1-D binned array along
//     lambda_max where the normals either side are most alike. The cut is kept when, after
//     refinement, it makes the normals more coherent by at least min_normal_gain, the bare cut
//     by at least half that; else PCA "cannot improve" the cluster (a tube, a smoothly curved
//     leaf, two touching leaves facing the same way).
//  2. Separation constraint (divfrp.h): clusters the normals cannot improve are bipartitioned by
//     the modified DIVFRP when they hold distinct groups at the link radius.
//     Clusters with no gap either are cut at a narrow neck (neck_split.h): the least-conductance
//     spectral cut of the cluster's neighbour graph, kept when the contact it crosses is short
//     against the narrower side's width (two touching leaves facing almost the same way); its
//     boundary is then redrawn where the surface steps from one leaf onto the other.
//     Clusters without a neck are cut where their normal field jumps (sheet_split.h): the
//     least-conductance spectral cut of the neighbour graph weighted by the bend of smoothed
//     normals, kept when both sides continue through it (two blades that cross each other)
//     rather than end at it (a leaf's midrib fold or crease).
//  Every new part is split into its connected components; parts smaller than
//  min_cluster_points are spurious and join the cluster they touch at the end.
//  3. Outlier / incorrect-patch constraint (reassignment.h): points that fit a neighbouring
//     cluster's local plane better than their own (normal and distance) move there; then a
//     part of fewer than min_cluster_points that its cluster's links no longer reach joins the
//     cluster it is linked to most.
//
// Every threshold is derived from the data (data_scale.h): spacing = median nearest-neighbour
// distance, noise = median local plane residual; options override them. Deterministic: no
// randomness, no threading, fixed processing order; output ids are ordered by each cluster's
// smallest point index.

#include <cstddef>
#include <string>

#include "core/cluster/connected_components.h"
#include "core/cluster/point_set.h"
#include "core/cluster/tube_shape.h"

namespace avc::cluster {

struct ClusterOptions {
  // Scales; <= 0 means measure them on the data.
  double spacing = 0;  // m
  double noise = 0;    // m
  // Points closer than link_factor * spacing are neighbours (connectivity, gaps, reassignment).
  double link_factor = 5.0;
  // ... and on the same local surface: their offset rises at most asin(link_slope) above both
  // tangent planes, beyond noise_factor * noise (connected_components.h).
  double link_slope = 0.5;
  // ... and near the plane normal to the bisector of their two normals: the offset rises at most
  // asin(link_mean_slope) above it, beyond the same allowance (< 0: no such test). A chord of a
  // smoothly bent sheet is perpendicular to that bisector; between stacked leaves facing the
  // same way it runs along it (connected_components.h).
  double link_mean_slope = kSameSurfaceMeanSlope;
  // 1-D bin width of the normal split, in spacings.
  double bin_factor = 2.0;
  // Normal constraint: flat when sqrt(lambda_min) <= noise_factor * noise ...
  double noise_factor = 3.0;
  // ... or sqrt(lambda_min / lambda_mid) <= flatness_ratio (a leaf cupped by 1/5 of its width).
  double flatness_ratio = 0.2;
  // A normal split must raise normal coherence by this fraction of the points (0.1: two planes
  // meeting at more than ~37 degrees; a sheet bent smoothly through 60 degrees gains ~0.06).
  double min_normal_gain = 0.1;
  // ... and the cluster is not a tube: a stem or petiole, whose normals point away from its
  // longest axis, is not split by its normals (tube_shape.h; min_alignment > 1 turns it off).
  TubeRule tube;
  // Passes of point-wise refinement of a normal split and of an overlapping-sheet cut.
  int refinement_rounds = 4;
  // Smallest real cluster; 0 = automatic: 13 points (4 pi, a disc of radius two mean sample
  // spacings, the least a triangulated patch needs).
  int min_cluster_points = 0;
  int reassignment_rounds = 3;
  // Separation at a narrow neck (neck_split.h): k of the neighbour graph, Lanczos steps, the
  // normal-bend weighting (0 = unweighted) and the largest neck ratio (contact length / narrower
  // side's width) that is cut (0: only parts without any edge between them). A higher ratio
  // parts touching leaves more readily but starts cutting whole leaves across; the default lies
  // mid-way in the range where the Table 2 sets' results do not change (BENCHMARKS.md, "Where
  // the defaults come from"). The length estimate reads about 0.47 of the true length on a
  // straight cut across a uniform strip, so a strip six times longer than wide sits at the limit
  // and is cut across; elliptic blades three times longer than wide are not.
  int neck_neighbours = 10;
  int neck_lanczos_steps = 40;
  double neck_bend_factor = 16.0;
  double max_neck_ratio = 0.5;
  // A kept neck cut is redrawn on the graph weighted by the edges' elevation off the tangent
  // planes too (neck_split.h; 0 disables it), and adopted when at most neck_max_boundary_shift of
  // the smaller side changes side; then refinement_rounds of point-wise refinement. Without it,
  // strips of a wavy margin or a narrow tip stay with the touching leaf. A higher elevation
  // factor leaves such strips behind again; the shift limit rejects a redrawing that is really
  // another cut, and set too low it rejects needed ones (BENCHMARKS.md, "Where the defaults
  // come from").
  double neck_elevation_factor = 4.0;
  double neck_max_boundary_shift = 0.1;
  // Separation of overlapping sheets (sheet_split.h; the neck's k): blades that cross. Normals
  // are smoothed over the neighbours bent at most sheet_smoothing_factor times the cluster's
  // median neighbour bend: the bend b ~ angle^2 / 2 between two noisy normals is about
  // exponentially distributed, so 4 keeps all but 2^-4 = 6 % of a sheet's neighbours and drops a
  // crossing 3 times the typical angle (b 9 times). Edges weigh exp(-b / (sheet_bend_factor *
  // median b)) on the smoothed normals (the median edge 0.72; a 17-degree crossing, the smallest
  // on the Table 2 sets, the 1e-3 floor). The weights make the spectrum nearly degenerate, so the
  // Fiedler vector needs more Lanczos steps than the neck's: fewer leave crossing blades merged,
  // more only cost time. The cut is kept when neither side ends at it: edge bias (SheetRule) <=
  // max_sheet_edge_bias. A cut across one sheet shows a large bias (2/pi right at a straight
  // edge), crossing blades only sampling noise; the default lies between the two (BENCHMARKS.md,
  // "Where the defaults come from"); 0 disables the split.
  int sheet_lanczos_steps = 60;
  double sheet_smoothing_factor = 4.0;
  double sheet_bend_factor = 3.0;
  double max_sheet_edge_bias = 0.15;

  // Empty when usable; else a sentence naming the bad fields.
  std::string Validate() const;
};

struct ClusterReport {
  double spacing = 0;  // the values used (measured or given)
  double noise = 0;
  double link_radius = 0;
  int min_cluster_points = 0;
  size_t initial_components = 0;
  size_t normal_splits = 0;
  size_t separation_splits = 0;
  size_t neck_splits = 0;
  size_t sheet_splits = 0;
  size_t reassigned_points = 0;
  size_t outliers = 0;  // points left kUnassigned
  size_t clusters = 0;
};

// Throws std::invalid_argument naming the problem for fewer than 3 points, normals missing or of
// the wrong count, non-finite points or normals, zero normals, or invalid options.
Assignment ClusterPlant(const PointSet& set, const ClusterOptions& options = {},
                        ClusterReport* report = nullptr);

}  // namespace avc::cluster
