#include "report/report_html.h"

#include <fmt/format.h>

#include <ctime>
#include <stdexcept>

#include "core/util/file_io.h"
#include "report/report_assets.h"
#include "report/report_coverage.h"
#include "report/report_encode.h"
#include "report/report_inputs.h"
#include "report/report_scene.h"
#include "report/report_sections.h"
#include "report/report_svg.h"

namespace avc::report {
namespace {

namespace fs = std::filesystem;

std::string ReadScript(const char* path, const char* package) {
  try {
    std::string text = ReadFile(path);
    if (!text.empty()) return text;
  } catch (const std::runtime_error&) {
  }
  throw std::runtime_error(fmt::format("{}: cannot be read (Debian package {})", path, package));
}

// A script inlined into the page; "</script" inside it would close the element early.
std::string InlineScript(std::string code) {
  for (size_t at = code.find("</script"); at != std::string::npos; at = code.find("</script", at)) {
    code.replace(at, 2, "<\\/");
  }
  return "<script>\n" + code + "\n</script>\n";
}

std::string View3d(const ReportInputs& in) {
  std::string html =
      "<h2>3-D model</h2>\n<div class=\"toggles\">"
      "<label><input type=\"radio\" name=\"colour\" checked> colour by cluster</label>"
      "<label><input type=\"radio\" name=\"colour\" id=\"colour-by-vertex\"";
  html += in.mesh.colors.empty() ? " disabled" : "";
  html += "> by vertex colour</label>";
  html += fmt::format("<label><input type=\"checkbox\" id=\"show-points\"{}> MVS points{}</label>",
                      in.points ? "" : " disabled",
                      in.points
                          ? fmt::format(" ({} of {})", std::min(in.points->size(), kMaxPagePoints),
                                        in.points->size())
                          : "");
  html += fmt::format("<label><input type=\"checkbox\" id=\"show-cameras\"{}> cameras ({})</label>",
                      in.cameras.empty() ? " disabled" : "", in.cameras.size());
  html += "</div>\n<div id=\"view3d\"></div>\n<p id=\"view-status\">Loading the 3-D view…</p>\n";
  return html + "<script type=\"application/json\" id=\"avc-data\">" + SceneJson(in) +
         "</script>\n";
}

std::string StaticRenders(const ReportInputs& in) {
  const auto colours = FaceClusterColours(in.mesh);
  std::string html = fmt::format(
      "<h2>Static renders</h2>\n<p>The mesh ({} faces) projected orthographically, faces painted "
      "in their cluster's colour.</p>\n<div class=\"mesh-views\">\n",
      in.mesh.num_faces());
  for (MeshView view : {MeshView::kFront, MeshView::kSide, MeshView::kTop}) {
    html += MeshViewSvg(in.mesh, colours, view, 360);
  }
  return html + "</div>\n";
}

}  // namespace

std::string ReportHtml(const fs::path& scan_dir) {
  const ReportInputs in = LoadReportInputs(scan_dir);
  const std::string id = in.report.value("scan_id", scan_dir.filename().string());
  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>Scan {}</title>\n<style>\n{}</style>\n</head>\n<body>\n",
      EscapeHtml(id), kPageStyle);
  html += HeaderSection(in);
  html += KeyFiguresSection(in);
  html += View3d(in);
  html += StaticRenders(in);
  html += TimingsSection(in);
  html += ViewsSection(in);
  html += CoverageSection(in);
  html += ClustersSection(in);
  html += SurfaceSection(in);
  html += CalibrationSection(in);
  html += PlannerSection(in);
  html += ConfigurationSection(in);
  html += NotesSection(in);
  html += InlineScript(ReadScript(AVC_THREE_JS_PATH, "libjs-three"));
#ifdef AVC_ORBIT_CONTROLS_JS_PATH
  html += InlineScript(ReadScript(AVC_ORBIT_CONTROLS_JS_PATH, "libjs-three"));
#endif
  html += InlineScript(kPageScript);
  return html + "</body>\n</html>\n";
}

void WriteReportHtml(const fs::path& scan_dir) {
  WriteFileAtomically(scan_dir / "report.html", ReportHtml(scan_dir));
}

}  // namespace avc::report
