#pragma once

// Automatic plant segmentation of one image, with no hand-set thresholds (paper section 2.2:
// the builder needs a plant mask per image). Two features, each thresholded by Otsu:
//  - excess green (ExG) on chromaticity: the plant against anything that is not green (pot and
//    soil are brown or grey, so they are NOT plant here, which is what we want);
//  - distance from a background colour model estimated from the image border: any object
//    against a fairly uniform backdrop, e.g. a white figure on black (Middlebury dino).
// kAuto computes both and keeps the one whose Otsu split separates best, measured by
// eta = between-class variance / total variance of the feature, with ExG taken only when what
// it finds is green and given a preference factor (MaskOptions.green_min_exg, green_preference).
// Thresholds are Otsu's with hysteresis towards the background class (MaskOptions.hysteresis).
// The mask is then cleaned without eroding: carving tolerates a few wrong background votes, so
// keeping a 1-2 px wide leaf matters more than a perfectly tight outline.

#include <limits>
#include <opencv2/core/mat.hpp>
#include <string>

namespace avc::segmentation {

enum class MaskMethod { kAuto, kExcessGreen, kBackgroundDistance };

// "auto", "excess_green", "background_distance".
std::string MaskMethodName(MaskMethod method);

struct MaskOptions {
  MaskMethod method = MaskMethod::kAuto;
  // Feature value above which a pixel is plant; NaN = Otsu on this image (the default).
  double threshold = std::numeric_limits<double>::quiet_NaN();
  // Bins of the feature histogram Otsu searches (between the feature's min and max).
  int histogram_bins = 256;
  // ExG: R+G+B is floored at this fraction of the image's bright level (99th percentile), so
  // the noisy chromaticity of near-black pixels counts as background.
  double dark_fraction = 0.1;
  // Background model: width of the border strip sampled, as a fraction of min(width, height).
  double border_fraction = 0.02;
  // Background model: smallest per-channel spread (L*a*b* units, about one just-noticeable
  // difference), so a perfectly flat backdrop does not turn sensor noise into object.
  double background_min_scale = 2.0;
  // Hysteresis below the threshold t: pixels above t are plant, and so are pixels above
  // t - hysteresis * (t - mean of the background class) that connect to them, so the dimmer
  // rims and shaded parts of leaves stay attached. 0 = a single threshold.
  double hysteresis = 0.5;
  // kAuto: ExG is a candidate only when the class it calls plant is green, i.e. its mean ExG is
  // at least this (grey is 0, foliage 0.15..0.5); else ExG merely splits noise (white on black).
  double green_min_exg = 0.1;
  // kAuto: ExG wins when eta_exg * green_preference >= eta_background; 1 = pure "best
  // separability". Above 1 because ExG alone leaves the pot and soil out, which the background
  // distance separates too and so scores a little higher on; higher still, ExG would also win
  // where it splits the plant clearly worse. The default clears the ratios measured on potted
  // plants (BENCHMARKS.md, "Where the defaults come from").
  double green_preference = 1.25;
  // Cleanup: radius (px) of the closing disc; negative = derived from the image,
  // max(1, round(min(width, height) / 400)); 0 = no closing.
  int close_radius_px = -1;
  // Cleanup: components smaller than this fraction of the largest one are dropped ...
  double min_component_fraction = 0.002;
  // ... and so are those smaller than this fraction of the image.
  double min_component_image_fraction = 5e-5;
};

struct MaskResult {
  cv::Mat mask;                           // CV_8UC1, 255 plant, 0 background, the image's size
  MaskMethod method = MaskMethod::kAuto;  // the method used (never kAuto once segmented)
  double threshold = 0;      // on that method's feature; plant is feature > threshold ...
  double low_threshold = 0;  // ... and feature > low_threshold where connected to such pixels
  double separability = 0;   // eta of that split, in [0, 1] (0: the feature was constant)
};

// `bgr` is CV_8UC3. A featureless image (e.g. a single colour) gives an empty mask.
// Throws std::invalid_argument for an empty image, another pixel type, or bad options.
MaskResult SegmentPlant(const cv::Mat& bgr, const MaskOptions& options = {});

}  // namespace avc::segmentation
