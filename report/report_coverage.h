#pragma once

// Ground-truth coverage against the number of images, for the scan report: the scan's captures
// in order (framing frames left out), each placed by the scan's calibration from the state the
// arm and table reported, scored on gt_mesh.ply with the planner benchmark's metric (a surface
// sample counts when >= 3 views see it at a grazing angle under 75 deg, occlusion included;
// eval/coverage.h). Only simulated scans have a ground truth.

#include <optional>
#include <string>
#include <vector>

#include "report/report_inputs.h"

namespace avc::report {

struct CoverageCurve {
  std::vector<double> after;  // [k]: coverage of the first k + 1 images
  int kept = 0;               // views Phase 3 kept ...
  double kept_fraction = 0;   // ... and their coverage
  size_t samples = 0;         // ground-truth surface samples scored
};

// nullopt without a ground truth, a scan record, a calibration or any planned capture.
std::optional<CoverageCurve> CoverageOfCaptures(const ReportInputs& in);

// The report's "Coverage" section: the curve as a chart and the figures, or a line saying why
// there is none.
std::string CoverageSection(const ReportInputs& in);

}  // namespace avc::report
