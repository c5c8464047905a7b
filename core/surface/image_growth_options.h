#pragma once

// Parameters of Phase 2 with images (image_growth.h): how far a cell may grow, how finely its
// plane is gridded, and what the plant masks must say for a grid node to count as leaf.
// Distances are multiples of the point spacing, like every other surfacer threshold.

#include "core/surface/colour_model.h"

namespace avc::surface {

struct ImageGrowthOptions {
  // Grow with the images when the caller gives them; false keeps the geometric band growth.
  bool enabled = true;
  // Farthest a cell's outline may move, in spacings: enough to close the gaps multi-view
  // stereo leaves on a leaf (a missed strip of a blade, a margin seen edge-on), not so far that
  // the continuation of the fitted surface is a guess. Higher recovers more of narrow leaves for
  // some precision; 12 is where a broad leaf stops gaining (BENCHMARKS.md, "Where the defaults
  // come from").
  double max_growth_factor = 12.0;
  // Grid pitch on the cell's plane, in spacings: the grown outline is placed to this.
  double grid_factor = 0.5;
  // A node is leaf when at least this many views see plant at its projection...
  int min_plant_views = 3;
  // ...and fewer than this many see background there: one background view could be a mask or
  // calibration slip, two are a line of sight past the leaf (the visual hull, node by node).
  int min_background_views = 2;
  // Mask pixels count as background only this far (pixels) from any plant pixel: the masks'
  // edge is uncertain by a pixel or so, and so is each camera's projection.
  double edge_tolerance_px = 1.5;
  // The level set's curvature term: the grown region is smoothed by a Gaussian of this many
  // spacings and thresholded at one half (one Merriman-Bence-Osher step of curvature flow),
  // which removes spurs along mask noise without moving a straight outline. Smaller keeps more
  // of the narrow tips and blades but lets more mask noise through; half a spacing is about the
  // best on every simulated scan (BENCHMARKS.md, "Where the defaults come from").
  double smoothing_factor = 0.5;
  // Colour agreement: with the views' images, a node also needs the colours most of its plant
  // views show to agree with the cell's colour model (colour_model.h); false: the masks alone.
  bool colour_agreement = true;
  ColourModelOptions colour;
};

}  // namespace avc::surface
