#include "services/builder/reconstruction_output.h"

#include <fmt/format.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "core/camera/camera_io.h"
#include "core/geometry/point_cloud_io.h"
#include "core/mvs/mvs_points_io.h"

namespace avc::builder {
namespace fs = std::filesystem;

fs::path ChooseOutputDirectory(const fs::path& dataset_dir, const fs::path& requested) {
  if (!requested.empty()) return requested;
  fs::path normal = fs::weakly_canonical(dataset_dir);
  if (normal.filename().empty()) normal = normal.parent_path();  // "scans/rosette/"
  std::string name = normal.filename().string();
  if (name.empty()) name = "dataset";
  const fs::path base = fs::current_path() / (name + "-reconstruction");
  fs::path candidate = base;
  for (int suffix = 2; fs::exists(candidate) && !fs::is_empty(candidate); ++suffix) {
    candidate = base.string() + "-" + std::to_string(suffix);
  }
  return candidate;
}

// JPEG quality of the undistorted images: their colours, not their fine detail, are read back.
constexpr int kImageQuality = 95;

std::vector<std::string> WriteReconstruction(const fs::path& dir, const dataset::ViewSet& set,
                                             const Reconstruction& reconstruction,
                                             const BuildReport& report, bool overwrite) {
  if (!overwrite) {
    for (const char* product : {"ppr.bt", "points.ply"}) {
      if (fs::exists(dir / product)) {
        throw std::runtime_error(
            fmt::format("{} already exists; choose another output directory or allow overwriting",
                        (dir / product).string()));
      }
    }
  }
  fs::create_directories(dir / "masks");
  fs::create_directories(dir / "images");
  std::vector<std::string> written;
  reconstruction.proxy.WriteBinary(dir / "ppr.bt");
  written.push_back("ppr.bt");
  if (reconstruction.points.size() > 0) {
    mvs::WriteMvsPointsPly(dir / "points.ply", reconstruction.points);
    written.push_back("points.ply");
  }
  if (reconstruction.merged.size() > 0) {
    geometry::WritePointCloudPly(dir / "merged.ply", reconstruction.merged.cloud);
    written.push_back("merged.ply");
  }
  std::vector<camera::NamedCamera> cameras;
  for (const dataset::View& view : set.views) {
    fs::path mask_name = fs::path(view.name).filename();
    mask_name.replace_extension(".png");
    if (!view.mask.empty() && !cv::imwrite((dir / "masks" / mask_name).string(), view.mask)) {
      throw std::runtime_error("cannot write " + (dir / "masks" / mask_name).string());
    }
    written.push_back("masks/" + mask_name.string());
    // The undistorted image beside its mask: the surfacer's colour agreement reads it.
    if (!view.mask.empty() && !view.image.empty()) {
      fs::path image_name = mask_name;
      image_name.replace_extension(".jpg");
      if (!cv::imwrite((dir / "images" / image_name).string(), view.image,
                       {cv::IMWRITE_JPEG_QUALITY, kImageQuality})) {
        throw std::runtime_error("cannot write " + (dir / "images" / image_name).string());
      }
      written.push_back("images/" + image_name.string());
    }
    cameras.push_back({view.name, view.camera});
  }
  camera::WriteCamerasJson(dir / "cameras.json", cameras);
  written.push_back("cameras.json");
  // The soil level is a product (plant height is measured from it): a stale one must not stay.
  if (reconstruction.soil) {
    std::ofstream soil(dir / "soil.json");
    soil << SoilLevelToJson(*reconstruction.soil).dump(2) << "\n";
    if (!soil) throw std::runtime_error("cannot write " + (dir / "soil.json").string());
    written.push_back("soil.json");
  } else {
    fs::remove(dir / "soil.json");
  }
  std::ofstream json(dir / "build.json");
  json << BuildReportToJson(report).dump(2) << "\n";
  if (!json) throw std::runtime_error("cannot write " + (dir / "build.json").string());
  written.push_back("build.json");
  return written;
}

}  // namespace avc::builder
