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
  // the continuation of the fitted surface is a guess. On the simulated scans (`avc bench
  // surface --scans`) 8 / 12 / 16 give F@2mm 0.921 / 0.934 / 0.934 on the broadleaf, 0.711 /
  // 0.748 / 0.769 on the strap, precision 98.1 / 97.2 / 96.2 % on the broadleaf: 12, where the
  // broadleaf's gain ends.
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
  // which removes spurs along mask noise without moving a straight outline. Half a spacing
  // keeps more of the narrow tips and blades: on the simulated scans (`avc bench surface
  // --scans`) 1 / 0.5 / 0.25 give F@2mm 0.6130 / 0.6143 / 0.6149 on the rosette, 0.9498 /
  // 0.9509 / 0.9504 on the broadleaf, 0.8844 / 0.8890 / 0.8889 on the strap (precision 95.3 /
  // 95.3 / 94.9 %), the bushy plant 0.9827 / 0.9828 / 0.9828.
  double smoothing_factor = 0.5;
  // Colour agreement: with the views' images, a node also needs the colours most of its plant
  // views show to agree with the cell's colour model (colour_model.h); false: the masks alone.
  bool colour_agreement = true;
  ColourModelOptions colour;
};

}  // namespace avc::surface
