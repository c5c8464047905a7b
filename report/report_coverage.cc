#include "report/report_coverage.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/eval/coverage.h"
#include "core/kinematics/row_major_pose.h"
#include "report/report_encode.h"
#include "report/report_svg.h"

namespace avc::report {
namespace {

constexpr double kSamplesPerM2 = 20000;  // a few thousand samples on a plant: a second or two
constexpr uint64_t kSeed = 1;

}  // namespace

std::optional<CoverageCurve> CoverageOfCaptures(const ReportInputs& in) {
  if (!in.ground_truth || !in.scan || !in.calibration) return std::nullopt;
  std::vector<orchestrator::CaptureRecord> captures;
  for (const orchestrator::CaptureRecord& c : in.scan->captures) {
    if (c.phase == "initial" || c.phase == "active") captures.push_back(c);
  }
  if (captures.empty()) return std::nullopt;
  std::sort(captures.begin(), captures.end(),
            [](const orchestrator::CaptureRecord& a, const orchestrator::CaptureRecord& b) {
              return a.index < b.index;
            });
  const eval::CoverageModel model(*in.ground_truth, kSamplesPerM2, kSeed);
  const int needed = model.options().min_views;
  std::vector<int> counts(model.samples().points.size(), 0);
  std::vector<int> kept_counts = counts;
  CoverageCurve curve;
  curve.samples = counts.size();
  const auto fraction = [&](const std::vector<int>& c) {
    const auto covered = std::count_if(c.begin(), c.end(), [&](int n) { return n >= needed; });
    return c.empty() ? 0.0 : static_cast<double>(covered) / static_cast<double>(c.size());
  };
  for (const orchestrator::CaptureRecord& c : captures) {
    const camera::Camera camera = in.calibration->CameraAt(
        kinematics::IsometryFromRowMajor(c.reported_T_base_flange.data()), c.reported_table_angle);
    const std::vector<uint8_t> seen = model.SeenBy(camera);
    for (size_t s = 0; s < seen.size(); ++s) {
      counts[s] += seen[s];
      if (c.kept) kept_counts[s] += seen[s];
    }
    curve.kept += c.kept;
    curve.after.push_back(fraction(counts));
  }
  curve.kept_fraction = fraction(kept_counts);
  return curve;
}

std::string CoverageSection(const ReportInputs& in) {
  std::string html = "<h2>Coverage</h2>\n";
  std::optional<CoverageCurve> curve;
  try {
    curve = CoverageOfCaptures(in);
  } catch (const std::exception& error) {  // a damaged ground truth or pose: say so, go on
    return html + "<p>Coverage could not be computed: " + EscapeHtml(error.what()) + "</p>\n";
  }
  if (!curve) {
    return html +
           "<p>No ground truth (gt_mesh.ply, simulated scans only), scan record or calibration: "
           "no coverage curve.</p>\n";
  }
  html += fmt::format(
      "<p>Ground-truth surface seen by at least 3 images at under 75&deg; from its normal, "
      "occlusion included ({} samples), after each image in capture order: {:.1f} % after all "
      "{}; the {} views kept after pruning cover {:.1f} %.</p>\n",
      curve->samples, 100 * curve->after.back(), curve->after.size(), curve->kept,
      100 * curve->kept_fraction);
  return html + LineChartSvg(curve->after, "images", "coverage",
                             {static_cast<double>(curve->kept), curve->kept_fraction});
}

}  // namespace avc::report
