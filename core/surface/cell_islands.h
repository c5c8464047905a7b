#pragma once

// Phase 3 may leave one cell in several pieces (long triangles removed across a narrow part of a
// leaf, such as the neck of an arching tip). Phase 4 stitches only between cells, so each piece
// becomes a cell of its own (same cluster and plane) and is joined to the rest like any
// neighbour within the cluster's stitch distance.

#include <cstddef>
#include <vector>

#include "core/surface/cell.h"

namespace avc::surface {

// Every cell split into its connected pieces (faces sharing a vertex), in order: a cell's pieces
// follow each other in the order of their first face. *islands receives how many pieces were
// split off (0 when every cell was one piece).
std::vector<Cell> SplitCellsIntoPieces(std::vector<Cell> cells, size_t* islands);

}  // namespace avc::surface
