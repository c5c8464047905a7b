#pragma once

// Phase 4 of the paper's Algorithm 3 (lines 6-15): cells are joined into one surface. Cells
// whose boundaries come within the stitch distance are neighbours (Euclidean connectivity); the
// gap between two neighbours is triangulated: their nearby boundary vertices are projected on
// the plane of the two cells' mean normal and triangulated (2-D Delaunay), and a triangle is
// kept when it lies in the gap: it spans at least two cells, each of its edges within one cell
// is a free boundary edge of that cell on the far side, edges between cells are within the stitch
// distance, it faces within max_tilt of the mean normal, and it keeps every edge manifold and
// consistently oriented.

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

// mesh: joined cells (JoinCells); cell_normals and cell_labels per cell. New faces take the
// label of the cell holding most of their vertices (the first vertex's on a tie).
StitchStats StitchCells(geometry::Mesh& mesh, const std::vector<int>& vertex_cell,
                        const std::vector<Eigen::Vector3d>& cell_normals,
                        const std::vector<int32_t>& cell_labels, double stitch_distance,
                        double max_tilt_deg);

}  // namespace avc::surface
