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

// The fitted surface for the parts Phase 2 grew (the growth and Phase 3's refinement of a cell
// grown with images): its neighbourhood may widen as far as the front may go and an ordinary
// neighbourhood beyond, so a vertex far beyond the samples still bends with a patch of the
// nearest part of the leaf. Capped at the ordinary 4 spacings, a vertex out there kept the
// height carried out flat (`avc bench surface --scans`, broadleaf: widening to 8 spacings took
// the leaf area more than 2 mm off the truth from 35 to 28 cm^2); capped at the growth limit, a
// vertex near it saw only a strip of samples along the cell's edge, whose quadric tilts at random
// with their noise (a noisy cylinder's grown faces: 39 degrees off the surface on average, 9
// with the patch; image_growth_test.cc). Inside the samples the doubling stops long before.
FittedSurfaceOptions GrownPartFit(const FittedSurfaceOptions& fit,
                                  const ImageGrowthOptions& options);

// samples: the input positions cell.source_points index. spacing, alpha: Phase 1's (m).
ImageGrowthStats GrowCellWithImages(Cell& cell, const std::vector<Eigen::Vector3f>& samples,
                                    const ImageEvidence& evidence,
                                    const ClaimedElsewhere& claimed_elsewhere, double spacing,
                                    double alpha, const FittedSurfaceOptions& fit,
                                    const ImageGrowthOptions& options);

}  // namespace avc::surface
