#pragma once

// Parameters of the surfacer (paper §4, Algorithm 3). Every distance is a multiple of the point
// spacing, the median nearest-neighbour distance measured on the input (the paper's point:
// parameters come from the data, no per-plant tuning); each can be overridden.

#include <string>

#include "core/surface/fitted_surface.h"
#include "core/surface/image_growth_options.h"

namespace avc::surface {

struct SmoothingOptions {
  // Taubin's lambda|mu Laplacian (uniform weights): a shrinking step then an inflating one, so
  // noise is smoothed without the sheet shrinking or its boundary pulling in.
  int iterations = 3;  // lambda|mu pairs
  double lambda = 0.5;
  double mu = -0.53;
};

struct SurfaceOptions {
  // Point spacing (m); <= 0: measured (median nearest-neighbour distance of the usable points).
  double spacing = 0;
  // Noise (m) of the points across the surface; < 0: measured (median residual of local plane
  // fits, cluster/data_scale.h).
  double noise = -1;

  // A cluster is triangulated piece by piece: points linked by neighbours closer than
  // piece_link_factor * spacing on the same local surface (offsets within 3 noise of both
  // tangent planes). Stacked leaves in one cluster thus become separate cells.
  double piece_link_factor = 5.0;

  // Phase 1: a Delaunay triangle on the cluster's regression plane is kept when its
  // circumradius, on the plane and once lifted to 3-D, is at most alpha_factor * spacing. For
  // uniform random samples of density rho the median spacing is about 0.47 / sqrt(rho), and a
  // Delaunay triangle's circumradius exceeds 3 spacings with probability ~1.4 %, 4 spacings
  // with ~0.02 % (Miles' distribution), so 4 keeps a randomly sampled sheet whole while still
  // cutting the convex hull's long boundary slivers and wide concavities.
  double alpha_factor = 4.0;

  // Phase 2. With images (image_growth.h, when the caller gives them): a level set over each
  // cell's plane driven by the plant masks. Without (boundary_growth.h): outlines not near
  // another cell grow by the band the sampling leaves at a surface's edge, estimated from the
  // triangulation, times growth_scale (<= 0: chosen from the sampling's regularity).
  bool grow_boundary = true;
  ImageGrowthOptions image_growth;
  double growth_scale = 0;
  // An outline vertex with a point of another cell closer than this many spacings (about one
  // sampling step: the two surfaces continue into each other) does not grow: the gap there is
  // Phase 4's to close.
  double growth_clearance_factor = 2.0;

  // Phase 3: mesh modifications.
  SmoothingOptions cell_smoothing;
  // Faces with a 3-D edge longer than this many spacings are removed: beyond the 2 alpha a
  // Phase 1 triangle can span, so only faces stretched by growth or a fold go.
  double long_edge_factor = 10.0;
  // Faces on a boundary with quality 4 sqrt(3) area / sum(edge^2) below this (1 = equilateral)
  // are peeled off: the slivers a Delaunay boundary leaves.
  double min_boundary_quality = 0.1;
  // Boundary loops (other than a component's outer one) with a perimeter up to this many
  // spacings are holes and are filled (a gap of about 6 spacings across).
  double hole_perimeter_factor = 20.0;
  // Then each cell is subdivided this many times (1-to-4) and every vertex moved onto the
  // surface fitted to the cell's samples (surface_refinement.h); refine = false keeps the
  // piecewise-flat mesh through the samples.
  bool refine = true;
  int refine_subdivisions = 1;
  FittedSurfaceOptions fit;

  // Phase 4: cell merging. Boundary vertices of different cells closer than this many spacings
  // are stitched. Neighbouring clusters of one leaf are one Delaunay edge of the cloud apart
  // (1-4 spacings), and boundary smoothing pulls outlines in a little further. Lower leaves
  // leaves in pieces; higher bridges the gaps between neighbouring leaves (BENCHMARKS.md, "Where
  // the defaults come from").
  double stitch_factor = 3.5;
  // Cells of one cluster (pieces of one leaf that a narrow part, sampled by few points, leaves
  // apart) are stitched across gaps up to this many spacings; <= 0: stitch_factor. Wider than
  // stitch_factor, since within one cluster a bridge joins parts of one leaf (arching tips), at a
  // small cost in distance to the points (BENCHMARKS.md, "Where the defaults come from").
  double own_cluster_stitch_factor = 5.25;
  // A stitch triangle must face within this angle (degrees) of the two cells' mean normal: no
  // walls between stacked leaves.
  double max_stitch_tilt_deg = 60.0;
  // When >= 0, a stitch edge between cells of different clusters must join two points of one
  // local surface: its offset within 0.5 |d| of both vertices' tangent planes and within this
  // many |d| of the plane normal to the bisector of their normals, plus 3 noise (the clusterer's
  // link test, cluster/connected_components.h). On, it keeps more of a rosette's leaves in one
  // piece and the mesh nearer the points, but it also refuses bridges within one leaf where real
  // points' cells meet, losing leaf area: off by default (BENCHMARKS.md, "Where the defaults
  // come from").
  double stitch_link_mean_slope = -1;
  // A stitch triangle whose centroid lies nearer a third cell's vertex than its own cells' is
  // refused: at a rosette's centre, where leaf bases lie stacked a few millimetres apart, the
  // bridge between two leaves would pass over a third, and its faces would lie as stray pieces
  // on that leaf. On by default: more of a rosette's leaves in one piece, the leaf area of the
  // other plants about unchanged (BENCHMARKS.md, "Where the defaults come from").
  bool stitch_clear_of_other_cells = true;
  SmoothingOptions final_smoothing{2, 0.5, -0.53};
  // Connected pieces of fewer faces than this are dropped at the end (stray fragments).
  int min_component_faces = 3;

  // Empty when valid; else a sentence naming the bad field.
  std::string Validate() const;
};

// The distances in force for one run (m): options resolved against the spacing.
struct SurfaceThresholds {
  double spacing = 0;
  double noise = 0;
  double piece_link = 0;
  double alpha = 0;
  double long_edge = 0;
  double hole_perimeter = 0;
  double stitch_distance = 0;
  double own_cluster_stitch_distance = 0;
  double growth_clearance = 0;
  double growth_band = 0;  // measured after Phase 1 (boundary_growth.h), 0 when not growing
};

SurfaceThresholds ResolveThresholds(const SurfaceOptions& options, double spacing, double noise);

}  // namespace avc::surface
