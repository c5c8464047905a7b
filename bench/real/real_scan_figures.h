#pragma once

// The figures of one `avc reconstruct` output folder on a real scan against a reference mesh of
// the same plant (not ground truth: the scanner's own reconstruction): MVS points and mesh
// precision/recall, area and pieces, height and width, and each view's mask against the
// reference's silhouette.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace avc::bench {

struct RealScanFigureOptions {
  double tolerance_px = 6;  // mask figures: agreement distance
  int stride = 1;           // the views the output was made from
};

// The stage times, views and mask methods of an output folder (its build.json).
nlohmann::json ReadStageTimes(const std::filesystem::path& output);

// The reference is in the dataset's own frame and unit (as the scanner wrote both). Throws
// std::runtime_error naming the file when an output or the reference cannot be read.
nlohmann::json MeasureRealScan(const std::filesystem::path& dataset,
                               const std::filesystem::path& output,
                               const std::filesystem::path& reference,
                               const RealScanFigureOptions& options);

std::string FormatRealScanFigures(const nlohmann::json& figures);

}  // namespace avc::bench
