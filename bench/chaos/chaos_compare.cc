#include "bench/chaos/chaos_compare.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <set>

namespace avc::bench {
namespace {

std::string IdOf(const std::string& line) { return line.substr(0, line.find(' ')); }

// The first position where two image lists part, for the report.
std::string FirstDifference(const std::vector<std::string>& expected,
                            const std::vector<std::string>& got) {
  const auto [a, b] = std::mismatch(expected.begin(), expected.end(), got.begin(), got.end());
  return fmt::format("at #{}: expected \"{}\", got \"{}\"", a - expected.begin(),
                     a == expected.end() ? "(end)" : *a, b == got.end() ? "(end)" : *b);
}

}  // namespace

ChaosComparison CompareWithReference(const ChaosScanResult& reference, const ChaosScanResult& run) {
  ChaosComparison c;
  auto fail = [&c](std::string problem) { c.problems.push_back(std::move(problem)); };
  if (!run.error.empty()) {
    fail("the scan did not finish");
    return c;
  }
  if (run.fault && !run.fault_injected) fail("the scan ended before the kill");

  std::map<std::string, int> times;
  for (const std::string& line : run.captured) ++times[IdOf(line)];
  std::set<std::string> expected;
  for (const std::string& line : reference.captured) expected.insert(IdOf(line));
  for (const auto& [id, count] : times) {
    if (count > 1) c.duplicated.push_back(id);
    if (!expected.count(id)) c.extra.push_back(id);
  }
  for (const std::string& id : expected) {
    if (!times.count(id)) c.lost.push_back(id);
  }
  if (!c.lost.empty()) fail(fmt::format("images lost: {}", fmt::join(c.lost, ", ")));
  if (!c.duplicated.empty()) {
    fail(fmt::format("images recorded twice: {}", fmt::join(c.duplicated, ", ")));
  }
  if (!c.extra.empty())
    fail(fmt::format("images not in the reference: {}", fmt::join(c.extra, ", ")));
  for (const std::string& problem : run.record_problems) fail(problem);
  if (run.image_files != run.captures) {
    fail(fmt::format("{} image files for {} recorded captures", run.image_files, run.captures));
  }
  if (run.captured != reference.captured) {
    fail("captured images differ from the reference " +
         FirstDifference(reference.captured, run.captured));
  }

  if (run.truth_frames < run.captures) {
    fail(fmt::format("{} captures but only {} frames rendered", run.captures, run.truth_frames));
  } else {
    c.recaptured = run.truth_frames - run.captures;
    const size_t allowed = run.fault_injected ? 1 : 0;
    if (c.recaptured > allowed) {
      fail(fmt::format("{} frames rendered for {} captures (at most {} again)", run.truth_frames,
                       run.captures, allowed));
    }
  }

  c.kept_identical = run.kept == reference.kept;
  if (!c.kept_identical) {
    fail("kept images differ from the reference " + FirstDifference(reference.kept, run.kept));
  }
  c.mesh_identical =
      run.mesh_sha256 == reference.mesh_sha256 && run.mesh_bytes == reference.mesh_bytes;
  if (!c.mesh_identical) {
    fail(fmt::format("mesh.ply differs: {} bytes sha256 {} against {} bytes sha256 {}{}",
                     run.mesh_bytes, run.mesh_sha256.substr(0, 12), reference.mesh_bytes,
                     reference.mesh_sha256.substr(0, 12),
                     run.cameras_sha256 == reference.cameras_sha256 ? " (cameras.json identical)"
                                                                    : " (cameras.json differs)"));
  }
  return c;
}

}  // namespace avc::bench
