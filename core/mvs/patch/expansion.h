#pragma once

// PMVS expansion: from each patch, new patches in the empty neighbouring cells of the images
// that see it (the cell's ray meets the patch plane, the normal is copied, then refined).
// Breadth-first in waves: a wave's candidates are computed in parallel against a frozen cell
// grid, then committed serially in patch order, skipping those whose cell got filled meanwhile
// - so the result does not depend on the number of threads.

#include <cstdint>
#include <vector>

#include "core/mvs/mvs_progress.h"
#include "core/mvs/occupancy_lookup.h"
#include "core/mvs/patch/cell_grid.h"
#include "core/mvs/patch/patch.h"
#include "core/mvs/patch/patch_image.h"
#include "core/mvs/patch/patch_mvs.h"

namespace avc::mvs::patch {

// Expands from `start` (ids of alive patches) until a wave adds nothing; returns how many
// patches were added. `grids` must hold the alive patches and is kept up to date.
size_t Expand(const std::vector<uint32_t>& start, const std::vector<PatchImage>& images,
              const OccupancyLookup& lookup, const PatchMvsOptions& options, PatchSet* set,
              CellGrids* grids, const MvsProgress& progress);

}  // namespace avc::mvs::patch
