#include "report/report_html.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "tests/report/report_test_scan.h"
#include "tests/support/test_support.h"

namespace avc::report {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

size_t Count(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

std::string ErrorOf(const fs::path& dir) {
  try {
    ReportHtml(dir);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ReportHtml, ShowsTheScanItsFiguresViewsAndClusters) {
  TempDir dir("avc-report");
  testing::WriteTestScan(dir.path(), testing::Tetrahedron());
  const std::string html = ReportHtml(dir.path());
  EXPECT_NE(html.find("<h1>Scan synthetic-0042</h1>"), std::string::npos);
  EXPECT_NE(html.find("2023-11-14 22:13:20 UTC"), std::string::npos);
  EXPECT_NE(html.find("state DONE"), std::string::npos);
  EXPECT_NE(html.find("images captured 3, kept 2"), std::string::npos);
  EXPECT_NE(html.find("78.9 cm²"), std::string::npos);  // leaf area
  EXPECT_NE(html.find("height above the soil<b>12.3 cm"), std::string::npos);
  EXPECT_NE(html.find("9.9 cm"), std::string::npos);                        // width
  EXPECT_NE(html.find("456.0 cm³"), std::string::npos);                     // hull volume
  EXPECT_NE(html.find("<td class=\"num\">0.889</td>"), std::string::npos);  // ground truth
  for (int i = 0; i < 3; ++i) {
    const std::string view = "view_000" + std::to_string(i);
    EXPECT_NE(html.find("<td>" + view + ".png</td>"), std::string::npos) << view;
    EXPECT_NE(html.find("<td>reason of view " + std::to_string(i) + "</td>"), std::string::npos);
  }
  EXPECT_NE(html.find("<tr class=\"dropped\">"), std::string::npos);        // pruned view 1
  EXPECT_NE(html.find("<td class=\"num\">40.00</td>"), std::string::npos);  // cluster 0 area
  EXPECT_NE(html.find("<td class=\"num\">120.2</td>"), std::string::npos);  // its azimuth
  EXPECT_NE(html.find("<td class=\"num\">30.50</td>"), std::string::npos);  // BUILD seconds
  EXPECT_NE(html.find("<li>patch 3 seen by 1 view</li>"), std::string::npos);
  EXPECT_NE(html.find("cameras (2)"), std::string::npos);
  // The configuration each stage ran with: its SHA-256's start and file, or that none was named.
  EXPECT_NE(html.find("<tr><td>build</td><td>avc-builder</td><td>0123456789abcdef</td>"
                      "<td>config/avc-builder.toml</td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<tr><td>surface</td><td>avc-surfacer</td><td>not named</td><td>-</td></tr>"),
            std::string::npos);
  // The surfacer's account: counts, area after each phase, warnings.
  EXPECT_NE(html.find("9 clusters of 2900 points (4 left out"), std::string::npos);
  EXPECT_NE(html.find("77 stitch faces joined them into 2 connected pieces"), std::string::npos);
  EXPECT_NE(html.find("<td>2: outlines grown</td><td class=\"num\">79.0</td>"), std::string::npos);
  EXPECT_NE(
      html.find("<li>cluster 7 (2 points): fewer than 3 points; its points are left out</li>"),
      std::string::npos);
}

TEST(ReportHtml, IsSelfContained) {
  TempDir dir("avc-report");
  testing::WriteTestScan(dir.path(), testing::Tetrahedron());
  const std::string html = ReportHtml(dir.path());
  EXPECT_NE(html.find("WebGLRenderer"), std::string::npos);  // three.js inlined
  EXPECT_NE(html.find("OrbitControls"), std::string::npos);
  EXPECT_NE(html.find("id=\"avc-data\""), std::string::npos);
  const std::regex network(R"((src|href)\s*=\s*["']?\s*(https?:)?//)", std::regex::icase);
  EXPECT_FALSE(std::regex_search(html, network));
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
}

TEST(ReportHtml, EmbedsARenderInEachStaticView) {
  TempDir dir("avc-report");
  testing::WriteTestScan(dir.path(), testing::Tetrahedron());
  const std::string html = ReportHtml(dir.path());
  EXPECT_EQ(Count(html, "<svg class=\"mesh-view\""), 3u);
  // front, side, top: one picture each (tests/report/mesh_render_test.cc checks its pixels)
  EXPECT_EQ(Count(html, "<image width=\"360\" height=\"360\" href=\"data:image/png;base64,"), 3u);
}

TEST(ReportHtml, SameInputsGiveTheSameBytes) {
  TempDir dir("avc-report");
  testing::WriteTestScan(dir.path(), testing::WavySheet(12));
  WriteReportHtml(dir.path());
  const std::string first = testing::ReadFile(dir / "report.html");
  WriteReportHtml(dir.path());
  EXPECT_EQ(testing::ReadFile(dir / "report.html"), first);
}

TEST(ReportHtml, NotesMissingOptionalInputs) {
  TempDir dir("avc-report");
  testing::WriteTestScan(dir.path(), testing::Tetrahedron());
  fs::remove(dir / "model/points.ply");
  fs::remove(dir / "cameras.json");
  const std::string html = ReportHtml(dir.path());
  EXPECT_NE(html.find("model/points.ply is missing"), std::string::npos);
  EXPECT_NE(html.find("cameras.json is missing"), std::string::npos);
  EXPECT_NE(html.find("calibration.yaml is missing"), std::string::npos);
  EXPECT_NE(html.find("<h1>Scan synthetic-0042</h1>"), std::string::npos);
}

TEST(ReportHtml, NamesAMissingReportOrMesh) {
  TempDir dir("avc-report");
  testing::WriteTestScan(dir.path(), testing::Tetrahedron());
  fs::remove(dir / "report.json");
  EXPECT_NE(ErrorOf(dir.path()).find("report.json: missing"), std::string::npos);
  testing::WriteFile(dir / "report.json", "{\"scan_id\": ");
  EXPECT_NE(ErrorOf(dir.path()).find("report.json: not JSON"), std::string::npos);

  testing::WriteTestScan(dir.path(), testing::Tetrahedron());
  fs::remove(dir / "model/mesh.ply");
  EXPECT_NE(ErrorOf(dir.path()).find("mesh.ply: missing"), std::string::npos);
  testing::WriteFile(dir / "model/mesh.ply",
                     "ply\nformat binary_little_endian 1.0\nelement vertex 3\n");
  const std::string error = ErrorOf(dir.path());
  EXPECT_NE(error.find("mesh.ply"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(dir / "report.html"));
}

}  // namespace
}  // namespace avc::report
