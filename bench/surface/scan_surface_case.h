#pragma once

// `avc bench surface --scans`: Phase 2 with and without the images on real reconstructions.
// A preset's simulated 3 x 10 scan (bench/simulated_scan.h: 1280x960, noise) goes through the
// builder (undistortion, automatic masks, proxy, patch MVS, merging) and Algorithm 2, as a scan
// does; the same clusters are then surfaced with the band growth (no images) and with the
// image-driven level sets (the builder's masks), and both meshes are scored against the plant's
// leaves: where multi-view stereo left parts of a leaf without points, only the images can say
// how far the leaf goes.

#include <filesystem>
#include <string>
#include <vector>

#include "core/surface/image_growth_options.h"

namespace avc::bench {

struct ScanSurfaceRow {
  std::string preset;
  std::string method;  // "band growth (no images)" or "image level sets"
  bool ok = false;
  std::string error;
  size_t images = 0;
  size_t merged_points = 0;
  double leaf_area_ratio = 0;   // leaf area of the mesh nearest each leaf / the leaves' area
  double accuracy_mean = 0;     // m, mesh area samples on the leaves to the truth
  double precision_2mm = 0;     // of the mesh's leaf samples
  double recall_2mm = 0;        // of the leaves' samples
  double total_area_ratio = 0;  // the total area trait / the leaves' area
  double height_ratio = 0;      // the height trait / the organs' height above the soil
  double ground_error = 0;      // m, where the height is measured from (the soil found, else the
                                // proxy's base) minus the true soil's mean height
  bool soil_found = false;      // the builder found the soil (else the proxy's base was used)
  int leaves = 0;               // leaves of the plant
  int connected_leaves = 0;     // ... whose mesh faces are one piece (leaf_connectivity.h)
  int mostly_one_leaves = 0;    // ... whose largest piece holds >= 95 % of their faces' area
  size_t faces = 0;
  double seconds = 0;  // surfacing only
};

// Both rows for one preset; scan: the rendered scan folder (EnsureSimulatedScan); growth: the
// image level sets' options. Runs in a child process (the builder's threads stay out of the
// benchmark's process).
std::vector<ScanSurfaceRow> RunScanSurfaceCase(const std::string& preset,
                                               const std::filesystem::path& scan,
                                               const surface::ImageGrowthOptions& growth);

}  // namespace avc::bench
