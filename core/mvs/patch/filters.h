#pragma once

// PMVS's filters, each computed in parallel into per-patch decisions and applied in id order:
//  - visibility consistency (filterOutside): a patch in front of patches that other images see
//    behind it, with less support than they have, is an outlier;
//  - exact visibility (filterExact): images in which a patch is hidden by another leave its V*;
//    it goes when fewer than γ remain;
//  - regularity (filterNeighbor): a patch far from the plane of its neighbours goes;
//  - small groups (filterSmallGroups): connected groups of few patches go.
// Each filter rebuilds `grids` from the surviving patches.

#include "core/mvs/patch/cell_grid.h"
#include "core/mvs/patch/patch.h"
#include "core/mvs/patch/patch_image.h"
#include "core/mvs/patch/patch_mvs.h"

namespace avc::mvs::patch {

// Each returns the number of patches removed.
size_t FilterOutside(const std::vector<PatchImage>& images, const PatchMvsOptions& options,
                     PatchSet* set, CellGrids* grids);
size_t FilterExact(const std::vector<PatchImage>& images, const PatchMvsOptions& options,
                   PatchSet* set, CellGrids* grids);
size_t FilterRegularity(const std::vector<PatchImage>& images, const PatchMvsOptions& options,
                        PatchSet* set, CellGrids* grids);
size_t FilterSmallGroups(const std::vector<PatchImage>& images, const PatchMvsOptions& options,
                         PatchSet* set, CellGrids* grids);

}  // namespace avc::mvs::patch
