#pragma once

// Gives every view of a set a plant mask: masks that came with the data are kept, the others
// are computed with SegmentPlant, views in parallel (each view's result depends on its image
// only, so the output does not depend on thread timing).

#include <string>
#include <vector>

#include "core/dataset/view.h"
#include "core/segmentation/plant_mask.h"

namespace avc::segmentation {

struct ViewMask {
  std::string view;    // View::name
  bool given = false;  // the mask came with the data (method/threshold then unused)
  MaskMethod method = MaskMethod::kAuto;
  double threshold = 0;
  double separability = 0;
  double plant_fraction = 0;  // fraction of the image's pixels that are plant
};

struct MaskSummary {
  std::vector<ViewMask> views;  // in the set's order
  int computed = 0;             // masks made here
  int given = 0;                // masks kept
};

// Throws std::invalid_argument naming the view when its image is empty or not CV_8UC3, or a
// given mask is not CV_8UC1 of the image's size; nothing is changed then.
MaskSummary FillMissingMasks(dataset::ViewSet& set, const MaskOptions& options = {});

}  // namespace avc::segmentation
