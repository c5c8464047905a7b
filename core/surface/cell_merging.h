#pragma once

// Phase 4 of the paper's Algorithm 3 (lines 6-15): cells are joined into one surface. Cells
// whose boundaries come within the stitch distance are neighbours (Euclidean connectivity); the
// gap between two neighbours is triangulated: their nearby boundary vertices are projected on
// the plane of the two cells' mean normal and triangulated (2-D Delaunay), and a triangle is
// kept when it lies in the gap: it spans at least two cells, each of its edges within one cell
// is a free boundary edge of that cell on the far side, edges between cells are within the stitch
// distance, it faces within max_tilt of the mean normal, it keeps every edge manifold and
// consistently oriented, and it does not pass over or under a third cell (the vertex nearest its
// centroid is one of its own cells'), so that at a rosette's centre, where the leaf bases lie
// stacked a few millimetres apart, two leaves are not bridged across a third. The rule may ask
// more between cells of different clusters: that each such edge joins two points of one local
// surface (the clusterer's link test on the vertices' normals), so that stacked leaves are left
// apart while the clusters the normal constraint cut out of one bent leaf are joined again; and
// it may stitch the cells of one cluster across wider gaps.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry/mesh.h"
#include "core/surface/cell.h"

namespace avc::surface {

// All cells in one mesh (vertex indices shifted by cell); *vertex_cell receives each vertex's
// cell index.
geometry::Mesh JoinCells(const std::vector<Cell>& cells, std::vector<int>* vertex_cell);

struct StitchStats {
  size_t neighbour_pairs = 0;  // pairs of cells whose boundaries come within the distance
  size_t stitched_pairs = 0;   // ... that gained at least one triangle
  size_t faces = 0;            // triangles added
};

struct StitchRule {
  double distance = 0;              // m: the widest gap bridged between cells of two clusters
  double own_cluster_distance = 0;  // m: ... between cells of one cluster; <= 0: distance
  double max_tilt_deg = 60;
  // The link test (cluster::LinkRule) for edges between clusters; link_slope < 0 turns it off
  // (SurfaceOptions::stitch_link_mean_slope, off by default in the surfacer).
  float link_slope = 0.5f;
  float link_mean_slope = 0.1f;
  float link_allowance = 0;  // m
  // A stitch triangle is refused when the vertex nearest its centroid belongs to a third cell:
  // the bridge would pass over or under that cell (SurfaceOptions::stitch_clear_of_other_cells).
  bool clear_of_other_cells = true;
};

// mesh: joined cells (JoinCells); cell_normals and cell_labels per cell. New faces take the
// label of the cell holding most of their vertices (the first vertex's on a tie).
StitchStats StitchCells(geometry::Mesh& mesh, const std::vector<int>& vertex_cell,
                        const std::vector<Eigen::Vector3d>& cell_normals,
                        const std::vector<int32_t>& cell_labels, const StitchRule& rule);

}  // namespace avc::surface
