// avc report: report.html for a finished scan directory (report/report_html.h), the same
// page `avc scan` writes at its end; run again after changing the model or the page.

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "report/report_html.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {

void RegisterReport(CLI::App& root, int* exit_code) {
  auto dir = std::make_shared<std::string>();
  CLI::App* command = root.add_subcommand(
      "report",
      "Write DIR/report.html for a finished scan: one self-contained page that works offline\n"
      "(three.js inlined): scan id, date, state and images; leaf area, height, width, hull\n"
      "volume and clusters (and scores against the ground truth for simulated scans); a 3-D\n"
      "view of the mesh with its MVS points and the kept cameras; static front/side/top renders\n"
      "(shown when WebGL is missing, and printed); phase timings; the views; traits per cluster;\n"
      "calibration residuals; the planner's notes.\n"
      "Needs DIR/report.json and DIR/model/mesh.ply; other missing files are noted in the page.\n"
      "\n"
      "Example: avc report scans/plant-0001");
  command->add_option("dir", *dir, "scan directory (what `avc scan` wrote)")
      ->required()
      ->check(CLI::ExistingDirectory);
  SetGuardedRun(command, exit_code, [dir] {
    report::WriteReportHtml(*dir);
    std::cout << (std::filesystem::path(*dir) / "report.html").string() << "\n";
    return 0;
  });
}

}  // namespace avc::cli
