// `avc eval` end to end: files in, JSON / HTML / PNG out, through the library function and
// through the real executable.

#include "core/eval/eval_command.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <opencv2/imgcodecs.hpp>

#include "core/camera/camera_io.h"
#include "core/eval/eval_report_html.h"
#include "core/util/web_text.h"
#include "tests/core/eval/test_scenes.h"
#include "tests/support/test_support.h"

namespace avc::eval {
namespace {

using avc::testing::ReadFile;
using avc::testing::TempDir;
using avc::testing::WriteFile;

// Two 10 cm sheets side by side (leaf 0 and leaf 1), as an ascii PLY with face labels, scaled
// by `unit` (1 for metres, 1000 for millimetres).
std::string GroundTruthPly(double unit) {
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
      "property int label\nend_header\n";
  for (const auto& [x, y] :
       {std::pair{0.0, 0.0}, {0.1, 0.0}, {0.2, 0.0}, {0.0, 0.1}, {0.1, 0.1}, {0.2, 0.1}}) {
    ply += fmt::format("{} {} 0\n", x * unit, y * unit);
  }
  ply += "3 0 1 4 100\n3 0 4 3 100\n3 1 2 5 101\n3 1 5 4 101\n";
  return ply;
}

// Leaf 0 reconstructed 1 mm above, leaf 1 4 mm above, 1 mm grids: one point per line.
std::string ReconstructionXyz(double unit) {
  std::string xyz = "# x y z\n";
  for (const auto& [x0, z] : {std::pair{0.0, 0.001}, {0.1, 0.004}}) {
    const geometry::PointCloud grid = test::Grid(x0, x0 + 0.1, 0, 0.1, z, 0.001);
    for (const Eigen::Vector3f& p : grid.positions) {
      xyz += fmt::format("{} {} {}\n", p.x() * unit, p.y() * unit, p.z() * unit);
    }
  }
  return xyz;
}

// Three cameras 0.5 m above the sheets, looking at their middle.
std::vector<camera::NamedCamera> Cameras() {
  return {{"left.png", test::LookAt({0, 0.05, 0.5}, {0.1, 0.05, 0})},
          {"middle.png", test::LookAt({0.1, 0.05, 0.5}, {0.1, 0.05, 0})},
          {"right.png", test::LookAt({0.2, 0.05, 0.5}, {0.1, 0.05, 0})}};
}

struct Files {
  TempDir dir;
  std::filesystem::path gt = dir / "gt.ply";
  std::filesystem::path reconstruction = dir / "rec.xyz";
  std::filesystem::path cameras = dir / "cameras.json";
  Files(double unit = 1) {
    WriteFile(gt, GroundTruthPly(unit));
    WriteFile(reconstruction, ReconstructionXyz(unit));
    camera::WriteCamerasJson(cameras, Cameras());
  }
  EvalCommandOptions Options() const {
    EvalCommandOptions options;
    options.ground_truth = gt;
    options.reconstruction = reconstruction;
    options.samples_per_m2 = 2e5;
    options.seed = 5;
    return options;
  }
};

TEST(EvalCommand, WritesJsonHtmlAndPlot) {
  Files files;
  EvalCommandOptions options = files.Options();
  options.cameras = files.cameras;
  options.json_output = files.dir / "report.json";
  options.html_output = files.dir / "report.html";
  options.plot_output = files.dir / "plot.png";
  const nlohmann::json returned = RunEvalCommand(options);

  const nlohmann::json report = nlohmann::json::parse(ReadFile(options.json_output));
  EXPECT_EQ(report, returned);
  for (const char* key : {"accuracy", "completeness", "scores", "thresholds", "organs",
                          "ground_truth", "reconstruction", "sampling", "area_ratio", "area_note",
                          "chamfer_mean", "coverage", "inputs"}) {
    EXPECT_TRUE(report.contains(key)) << key;
  }
  EXPECT_EQ(report["units"], "metres");
  EXPECT_EQ(report["reconstruction"]["kind"], "point_cloud");
  EXPECT_EQ(report["reconstruction"]["vertices"], 20000);
  EXPECT_EQ(report["sampling"]["seed"], 5);
  EXPECT_EQ(report["inputs"]["ground_truth"], files.gt.string());
  EXPECT_TRUE(report["area_ratio"].is_null());
  EXPECT_NEAR(report["ground_truth"]["area_m2"].get<double>(), 0.02, 1e-9);
  EXPECT_NEAR(report["accuracy"]["mean"].get<double>(), 0.0025, 1e-8);
  EXPECT_NEAR(report["accuracy"]["rmse"].get<double>(), std::sqrt((1.0 + 16.0) / 2) * 1e-3, 1e-8);
  ASSERT_EQ(report["scores"].size(), 4u);
  EXPECT_EQ(report["scores"][1]["threshold"], 0.002);
  EXPECT_EQ(report["scores"][1]["precision"], 0.5);
  EXPECT_EQ(report["scores"][2]["precision"], 1.0);
  EXPECT_EQ(report["scores"][2]["recall"], 1.0);
  ASSERT_EQ(report["organs"].size(), 2u);
  EXPECT_EQ(report["organs"][1]["name"], "leaf 1");
  EXPECT_NEAR(report["organs"][1]["accuracy"]["mean"].get<double>(), 0.004, 1e-8);
  EXPECT_EQ(report["coverage"]["cameras"], 3);
  EXPECT_EQ(report["coverage"]["min_views"], 3);
  EXPECT_EQ(report["coverage"]["fraction"], 1.0);
  EXPECT_EQ(report["coverage"]["samples"], report["ground_truth"]["samples"]);

  const std::string png = ReadFile(options.plot_output);
  const cv::Mat plot = cv::imdecode(std::vector<uint8_t>(png.begin(), png.end()), cv::IMREAD_COLOR);
  EXPECT_EQ(plot.cols, 960);
  EXPECT_EQ(plot.rows, 400);
  const std::string html = ReadFile(options.html_output);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("data:image/png;base64,iVBORw0KGgo"), std::string::npos);
  EXPECT_NE(html.find("leaf 1"), std::string::npos);
  EXPECT_NE(html.find("Coverage by views"), std::string::npos);

  // Same inputs and seed → the same bytes.
  const std::string first_json = ReadFile(options.json_output);
  const std::string first_html = html;
  RunEvalCommand(options);
  EXPECT_EQ(ReadFile(options.json_output), first_json);
  EXPECT_EQ(ReadFile(options.html_output), first_html);
}

TEST(EvalCommand, ScaleReadsMillimetreFiles) {
  Files metres;
  Files millimetres(1000);
  EvalCommandOptions options = millimetres.Options();
  options.scale = 0.001;
  const nlohmann::json scaled = RunEvalCommand(options);
  const nlohmann::json reference = RunEvalCommand(metres.Options());
  EXPECT_NEAR(scaled["accuracy"]["mean"].get<double>(), reference["accuracy"]["mean"].get<double>(),
              1e-9);
  EXPECT_EQ(scaled["scores"], reference["scores"]);
  // Unscaled, a 200 mm-wide plant read as 200 m is refused with a hint.
  options.scale = 1;
  try {
    RunEvalCommand(options);
    ADD_FAILURE() << "a millimetre file read as metres was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("millimetres"), std::string::npos) << e.what();
  }
}

TEST(EvalCommand, MeshReconstructionFromPly) {
  Files files;
  // The ground truth itself, as the reconstruction: a mesh, so areas are compared.
  EvalCommandOptions options = files.Options();
  options.reconstruction = files.gt;
  const nlohmann::json report = RunEvalCommand(options);
  EXPECT_EQ(report["reconstruction"]["kind"], "mesh");
  EXPECT_DOUBLE_EQ(report["area_ratio"].get<double>(), 1.0);
  EXPECT_EQ(report["scores"][0]["fscore"], 1.0);
}

TEST(EvalCommand, BadInputsNameTheFile) {
  Files files;
  auto error_of = [](const EvalCommandOptions& options) {
    try {
      RunEvalCommand(options);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EvalCommandOptions missing = files.Options();
  missing.reconstruction = files.dir / "nothing.ply";
  EXPECT_NE(error_of(missing).find("reconstruction " + missing.reconstruction.string() +
                                   ": no such file"),
            std::string::npos);
  WriteFile(files.dir / "broken.ply",
            "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n");
  EvalCommandOptions broken = files.Options();
  broken.ground_truth = files.dir / "broken.ply";
  EXPECT_NE(error_of(broken).find("broken.ply"), std::string::npos) << error_of(broken);
  EvalCommandOptions cloud_as_gt = files.Options();
  cloud_as_gt.ground_truth = files.reconstruction;
  EXPECT_NE(error_of(cloud_as_gt).find("rec.xyz"), std::string::npos) << error_of(cloud_as_gt);
  WriteFile(files.dir / "bad.json", "[{\"width\": 640}");
  EvalCommandOptions bad_cameras = files.Options();
  bad_cameras.cameras = files.dir / "bad.json";
  EXPECT_NE(error_of(bad_cameras).find("bad.json: not valid JSON"), std::string::npos)
      << error_of(bad_cameras);
  std::vector<camera::NamedCamera> skewed = Cameras();
  skewed[2].camera.T_cam_world.linear() *= 1.5;
  camera::WriteCamerasJson(files.dir / "skewed.json", skewed);
  bad_cameras.cameras = files.dir / "skewed.json";
  EXPECT_NE(error_of(bad_cameras).find("skewed.json: camera 2 (right.png): T_cam_world's rotation"),
            std::string::npos)
      << error_of(bad_cameras);
  EvalCommandOptions bad_scale = files.Options();
  bad_scale.scale = -1;
  EXPECT_NE(error_of(bad_scale).find("--scale -1"), std::string::npos);
}

TEST(Reports, Base64MatchesRfc4648Vectors) {
  auto encode = [](const std::string& text) {
    return avc::Base64Encode(std::vector<uint8_t>(text.begin(), text.end()));
  };
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foob"), "Zm9vYg==");
  EXPECT_EQ(encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(avc::Base64Encode(std::vector<uint8_t>{0xff, 0xfe, 0x00}), "//4A");
}

// Runs a shell command, returning its exit code and combined output.
std::pair<int, std::string> RunShell(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return {-1, "popen failed"};
  std::string output;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof(buffer), pipe)) output.append(buffer, n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

TEST(EvalCommand, TheAvcExecutable) {
  Files files;
  const std::string avc = avc::testing::Executable("avc").string();
  const auto [code, output] = RunShell(fmt::format(
      "'{}' eval --gt '{}' --reconstruction '{}' --samples-per-m2 2e5 --thresholds 0.002,0.005 "
      "--cameras '{}' --json '{}'",
      avc, files.gt.string(), files.reconstruction.string(), files.cameras.string(),
      (files.dir / "out.json").string()));
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(output.find("precision%"), std::string::npos) << output;
  EXPECT_NE(output.find("coverage"), std::string::npos) << output;
  const nlohmann::json report = nlohmann::json::parse(ReadFile(files.dir / "out.json"));
  EXPECT_EQ(report["thresholds"], (std::vector<double>{0.002, 0.005}));
  // --json - prints the same document as the last line.
  const auto [stdout_code, stdout_output] = RunShell(fmt::format(
      "'{}' eval --gt '{}' --reconstruction '{}' --samples-per-m2 2e5 --thresholds 0.002,0.005 "
      "--cameras '{}' --json -",
      avc, files.gt.string(), files.reconstruction.string(), files.cameras.string()));
  ASSERT_EQ(stdout_code, 0) << stdout_output;
  const size_t last_line = stdout_output.rfind('\n', stdout_output.size() - 2);
  EXPECT_EQ(nlohmann::json::parse(stdout_output.substr(last_line + 1)), report);
  EXPECT_EQ(report["scores"][0]["precision"], 0.5);
  EXPECT_EQ(report["coverage"]["fraction"], 1.0);

  const auto [missing_code, missing_output] =
      RunShell(fmt::format("'{}' eval --gt '{}' --reconstruction '{}'", avc,
                           (files.dir / "nope.ply").string(), files.reconstruction.string()));
  EXPECT_NE(missing_code, 0);
  EXPECT_NE(missing_output.find("avc eval: ground truth"), std::string::npos) << missing_output;
  EXPECT_NE(missing_output.find("nope.ply"), std::string::npos) << missing_output;
}

}  // namespace
}  // namespace avc::eval
