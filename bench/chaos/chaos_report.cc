#include "bench/chaos/chaos_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>

#include "bench/summary.h"

namespace avc::bench {
namespace {

size_t Passed(const std::vector<ChaosRow>& rows) {
  size_t passed = 0;
  for (const ChaosRow& row : rows) passed += row.comparison.ok();
  return passed;
}

size_t IdenticalMeshes(const std::vector<ChaosRow>& rows) {
  size_t identical = 0;
  for (const ChaosRow& row : rows) identical += row.comparison.mesh_identical;
  return identical;
}

}  // namespace

void PrintChaosTable(std::ostream& out, const std::string& title,
                     const std::vector<ChaosRow>& rows) {
  out << title << "\n"
      << fmt::format(
             "{:<12} {:<7} {:<13} {:>6} {:>7} {:>8} {:>8} {:>6} {:>6} {:>4} {:>5} {:>7}  {}\n",
             "scan", "cell", "killed", "at s", "resumes", "restarts", "captures", "images",
             "frames", "kept", "mesh", "wall s", "result");
  for (const ChaosRow& row : rows) {
    const ChaosScanResult& r = row.result;
    const ChaosComparison& c = row.comparison;
    const std::string victim = r.fault ? r.fault->victim : "-";
    const std::string at = r.fault_injected ? fmt::format("{:.1f}", r.killed_at_s) : "-";
    out << fmt::format(
        "{:<12} {:<7} {:<13} {:>6} {:>7} {:>8} {:>8} {:>6} {:>6} {:>4} {:>5} {:>7.1f}  {}\n",
        row.name, r.cell, victim, at, r.resumes, r.restarts, r.captures, r.image_files,
        r.truth_frames, r.kept.size(), c.mesh_identical ? "same" : "DIFF", r.wall_s,
        c.ok() ? "ok" : c.problems.front());
  }
  out << "\n";
}

bool PrintChaosSummary(std::ostream& out, const ChaosRow& reference,
                       const std::vector<ChaosRow>& trials, const std::vector<ChaosRow>& cells,
                       double cells_wall_s) {
  std::map<std::string, std::pair<int, int>> by_victim;  // survived, tried
  size_t images = 0, lost = 0, duplicated = 0, recaptured = 0;
  std::vector<double> walls;
  for (const std::vector<ChaosRow>* group : {&trials, &cells}) {
    for (const ChaosRow& row : *group) {
      images += row.result.captures;
      lost += row.comparison.lost.size();
      duplicated += row.comparison.duplicated.size();
      recaptured += row.comparison.recaptured;
    }
  }
  for (const ChaosRow& row : trials) {
    if (!row.result.fault) continue;
    auto& [survived, tried] = by_victim[row.result.fault->victim];
    survived += row.comparison.ok();
    ++tried;
    walls.push_back(row.result.wall_s);
  }
  std::vector<std::string> victims;
  for (const auto& [victim, counts] : by_victim) {
    victims.push_back(fmt::format("{} {}/{}", victim, counts.first, counts.second));
  }
  const Summary wall = Summarize(walls);
  out << fmt::format("Trials passed: {}/{}; faults survived: {}\n", Passed(trials), trials.size(),
                     fmt::join(victims, ", "));
  out << fmt::format(
      "Images: {} recorded in trials and cells, {} lost, {} duplicated; {} frames rendered "
      "again after kills\n",
      images, lost, duplicated, recaptured);
  out << fmt::format("Meshes identical to the reference: {}/{} trials, {}/{} concurrent cells\n",
                     IdenticalMeshes(trials), trials.size(), IdenticalMeshes(cells), cells.size());
  out << fmt::format("Wall time: reference {:.1f} s; trials median {:.1f} s, max {:.1f} s\n",
                     reference.result.wall_s, wall.median, wall.max);
  std::vector<std::string> cell_walls;
  for (const ChaosRow& row : cells) {
    cell_walls.push_back(fmt::format("{} {:.1f} s", row.result.cell, row.result.wall_s));
  }
  if (!cells.empty()) {
    out << fmt::format("Concurrent cells: {}/{} passed, {:.1f} s for all ({})\n", Passed(cells),
                       cells.size(), cells_wall_s, fmt::join(cell_walls, ", "));
  }
  return reference.comparison.ok() && Passed(trials) == trials.size() &&
         Passed(cells) == cells.size();
}

nlohmann::json ChaosRowJson(const ChaosRow& row) {
  const ChaosScanResult& r = row.result;
  const ChaosComparison& c = row.comparison;
  nlohmann::json json = {{"name", row.name},
                         {"cell", r.cell},
                         {"passed", c.ok()},
                         {"problems", c.problems},
                         {"fault_injected", r.fault_injected},
                         {"resumes", r.resumes},
                         {"restarts", r.restarts},
                         {"captures", r.captures},
                         {"image_files", r.image_files},
                         {"truth_frames", r.truth_frames},
                         {"kept", r.kept.size()},
                         {"lost", c.lost},
                         {"duplicated", c.duplicated},
                         {"extra", c.extra},
                         {"recaptured", c.recaptured},
                         {"kept_identical", c.kept_identical},
                         {"mesh_identical", c.mesh_identical},
                         {"mesh_bytes", r.mesh_bytes},
                         {"mesh_sha256", r.mesh_sha256},
                         {"cameras_sha256", r.cameras_sha256},
                         {"recordings", r.recordings},
                         {"wall_s", r.wall_s}};
  if (r.fault) {
    json["victim"] = r.fault->victim;
    json["planned_at_s"] = r.fault->at_s;
    json["killed_at_s"] = r.killed_at_s;
  }
  if (!r.error.empty()) json["error"] = r.error;
  return json;
}

}  // namespace avc::bench
