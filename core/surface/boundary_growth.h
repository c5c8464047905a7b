#pragma once

// Where the paper's Phase 2 goes (Algorithm 3 line 3): cell boundaries are grown outwards.
// The paper grows them with level sets driven by the images; until that is implemented, this
// geometric growth closes the band every sampled surface loses at its edge: the outermost
// samples lie inside the true outline, by about half a sample's share of area per unit of
// outline. Growth only moves outline vertices that no other cell is near (there Phase 4
// stitches instead), along the surface's tangent plane at the vertex, so curvature carries on.

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <vector>

#include "core/surface/cell.h"

namespace avc::surface {

// The band width (m) missing at a cell outline: a Delaunay triangle holds half a sample's
// share of area on average, an outline vertex has half its share outside, so the band is
// mean triangle area / mean outline edge length over all cells (h / 2 for a regular grid of
// pitch h). 0 when there are no faces.
// The band grows with the sampling's irregularity: r = spacing / sqrt(2 * mean triangle area)
// (the median nearest-neighbour distance against the mean distance per sample) is about 1.0 on
// an even sampling (grid, spiral, voxel averages) and 0.47 for uniform random samples, whose
// outermost points lie deeper inside (measured on discs: the band above is exact on an even
// sampling and about half the missing one on a random sampling). With scale <= 0 the band is
// multiplied by 1 + kRandomSamplingExtraBand * clamp((1 - r) / 0.53, 0, 1), else by scale.
// The extra is 0.6, not the discs' 1.0: on leaves' narrow tips and wavy, concave margins an
// outward band overshoots, and 1.0 overstates the simulated plants' leaf areas (BENCHMARKS.md,
// "Where the defaults come from").
inline constexpr double kRandomSamplingExtraBand = 0.6;
double EstimateBoundaryBand(const std::vector<Cell>& cells, double spacing, double scale);

struct GrowthStats {
  size_t vertices = 0;  // outline vertices moved out (new vertices)
  size_t faces = 0;     // faces added between the old and the new outline
};

// Grows the outer loops of the cell's mesh by band. is_free(vertex) says whether a vertex may
// grow (no other cell near). The new vertices (source_points -1, the colour of the vertex they
// grew from) are appended; the strip between old and new outline is triangulated.
GrowthStats GrowOuterBoundary(Cell& cell, double band, const std::function<bool(int)>& is_free);

}  // namespace avc::surface
