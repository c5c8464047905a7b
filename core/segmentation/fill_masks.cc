#include "core/segmentation/fill_masks.h"

#include <tbb/parallel_for.h>

#include <opencv2/core.hpp>
#include <stdexcept>

namespace avc::segmentation {
namespace {

void CheckView(const dataset::View& view, size_t index) {
  const std::string where =
      "FillMissingMasks: view " + std::to_string(index) + " '" + view.name + "'";
  if (view.image.empty()) throw std::invalid_argument(where + ": empty image");
  if (view.image.type() != CV_8UC3) {
    throw std::invalid_argument(where + ": image must be CV_8UC3 (BGR), got type " +
                                std::to_string(view.image.type()));
  }
  if (view.mask.empty()) return;
  if (view.mask.type() != CV_8UC1) {
    throw std::invalid_argument(where + ": given mask must be CV_8UC1, got type " +
                                std::to_string(view.mask.type()));
  }
  if (view.mask.size() != view.image.size()) {
    throw std::invalid_argument(where + ": given mask is " + std::to_string(view.mask.cols) + "x" +
                                std::to_string(view.mask.rows) + " but the image is " +
                                std::to_string(view.image.cols) + "x" +
                                std::to_string(view.image.rows));
  }
}

double PlantFraction(const cv::Mat& mask) {
  return static_cast<double>(cv::countNonZero(mask)) / static_cast<double>(mask.total());
}

}  // namespace

MaskSummary FillMissingMasks(dataset::ViewSet& set, const MaskOptions& options) {
  for (size_t i = 0; i < set.views.size(); ++i) CheckView(set.views[i], i);

  // Segment into a separate array first so a failure leaves the set untouched.
  std::vector<MaskResult> results(set.views.size());
  tbb::parallel_for(size_t{0}, set.views.size(), [&](size_t i) {
    const dataset::View& view = set.views[i];
    if (!view.mask.empty()) return;
    try {
      results[i] = SegmentPlant(view.image, options);
    } catch (const std::exception& error) {
      throw std::runtime_error("FillMissingMasks: view '" + view.name + "': " + error.what());
    }
  });

  MaskSummary summary;
  for (size_t i = 0; i < set.views.size(); ++i) {
    dataset::View& view = set.views[i];
    ViewMask info;
    info.view = view.name;
    info.given = !view.mask.empty();
    if (info.given) {
      ++summary.given;
    } else {
      view.mask = results[i].mask;
      info.method = results[i].method;
      info.threshold = results[i].threshold;
      info.separability = results[i].separability;
      ++summary.computed;
    }
    info.plant_fraction = PlantFraction(view.mask);
    summary.views.push_back(info);
  }
  return summary;
}

}  // namespace avc::segmentation
