#include "bench/surface/surface_targets.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>

namespace avc::bench {
namespace {

bool IsOurs(const SurfaceMethodResult& method) { return method.method.starts_with("ours"); }

// A target holds when `holds` is true for each of our results on every preset; the detail
// lists the results where it fails.
TargetCheck Check(
    const std::string& target, const std::vector<SurfaceCaseResult>& cases,
    const std::function<bool(const SurfaceCaseResult&, const SurfaceMethodResult&)>& holds,
    const std::function<std::string(const SurfaceMethodResult&)>& figure) {
  TargetCheck check{target, true, ""};
  for (const SurfaceCaseResult& c : cases) {
    for (const SurfaceMethodResult& m : c.methods) {
      if (!IsOurs(m)) continue;
      if (m.ok && holds(c, m)) continue;
      check.met = false;
      check.detail += fmt::format("{}{} {}: {}", check.detail.empty() ? "" : "; ", c.preset,
                                  m.method, m.ok ? figure(m) : "failed");
    }
  }
  return check;
}

}  // namespace

std::vector<TargetCheck> CheckSurfaceTargets(const std::vector<SurfaceCaseResult>& cases) {
  std::vector<TargetCheck> checks;
  checks.push_back(Check(
      "area ratio 0.9-1.1", cases,
      [](const auto&, const auto& m) { return m.area_ratio >= 0.9 && m.area_ratio <= 1.1; },
      [](const auto& m) { return fmt::format("{:.3f}", m.area_ratio); }));
  checks.push_back(Check(
      "RMSE below every baseline", cases,
      [](const SurfaceCaseResult& c, const SurfaceMethodResult& m) {
        for (const SurfaceMethodResult& other : c.methods) {
          if (!IsOurs(other) && other.ok && other.rmse <= m.rmse) return false;
        }
        return true;
      },
      [](const auto& m) { return fmt::format("{:.3f} mm", 1e3 * m.rmse); }));
  checks.push_back(Check(
      ">= 90 % of leaves one component", cases,
      [](const auto&, const auto& m) { return m.connected_fraction >= 0.9; },
      [](const auto& m) { return fmt::format("{}/{}", m.connected_leaves, m.leaves); }));
  checks.push_back(Check(
      "height trait within 2 %", cases,
      [](const auto&, const auto& m) { return std::abs(m.height_ratio - 1.0) <= 0.02; },
      [](const auto& m) { return fmt::format("{:.3f}", m.height_ratio); }));
  checks.push_back(Check(
      "<= 10 s for 3000 points", cases,
      [](const auto&, const auto& m) { return m.seconds + m.cluster_seconds <= 10.0; },
      [](const auto& m) { return fmt::format("{:.2f} s", m.seconds + m.cluster_seconds); }));
  return checks;
}

}  // namespace avc::bench
