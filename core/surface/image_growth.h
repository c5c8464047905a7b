#pragma once

// Phase 2 of the paper's Algorithm 3 with the images: each cell's outline grows as a level set
// on a grid over the cell's plane, with a speed the images give node by node. A node is lifted
// onto the cell's surface (the mesh's height carried outwards, then the fitted surface of the
// cell's samples, fitted_surface.h) and judged by the plant masks (image_evidence.h): the front
// moves at unit speed through nodes the views see as plant, in colours that agree with the
// cell's colour model (colour_model.h, fitted to its points' colours), and stops at nodes they
// see as background or in another colour, at nodes nearer another cell's points (the neighbouring
// cells, which Phase 4 stitches to), and after max_growth. The front's arrival times are the
// monotone level set; one Merriman-Bence-Osher step (Gaussian, threshold one half) is its curvature
// term. The grown region is then triangulated with the cell's own vertices (2-D Delaunay on the
// plane, alpha as in Phase 1), so the cell keeps every vertex and gains new ones (source_points
// -1).

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <vector>

#include "core/surface/cell.h"
#include "core/surface/fitted_surface.h"
#include "core/surface/image_evidence.h"
#include "core/surface/image_growth_options.h"

namespace avc::surface {

struct ImageGrowthStats {
  size_t cells_grown = 0;         // cells that gained area
  size_t nodes_plant = 0;         // judged nodes the views see as plant
  size_t nodes_background = 0;    // ... as background (the front stops)
  size_t nodes_unknown = 0;       // ... in too few views' frames (the front stops)
  size_t nodes_other_colour = 0;  // ... as plant of another colour than the cell's (stops)
  size_t nodes_claimed = 0;       // nearer another cell (the front stops)
  size_t nodes_grown = 0;         // in the grown region after the curvature step
  size_t vertices_added = 0;

  ImageGrowthStats& operator+=(const ImageGrowthStats& other);
};

// True when a point belongs to another cell's surface rather than this one's.
using ClaimedElsewhere = std::function<bool(const Eigen::Vector3d&)>;

// samples: the input positions cell.source_points index. spacing, alpha: Phase 1's (m).
ImageGrowthStats GrowCellWithImages(Cell& cell, const std::vector<Eigen::Vector3f>& samples,
                                    const ImageEvidence& evidence,
                                    const ClaimedElsewhere& claimed_elsewhere, double spacing,
                                    double alpha, const FittedSurfaceOptions& fit,
                                    const ImageGrowthOptions& options);

}  // namespace avc::surface
