#include "bench/clustering/clustering_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace avc::bench {
namespace {

std::string Cell(const nlohmann::json& result) {
  const std::string status = result.at("status");
  if (status == "skipped") return "skipped";
  if (status == "error") return "error";
  const nlohmann::json& accuracy = result.at("accuracy");
  const std::string percent =
      accuracy.is_null() ? "n/a" : fmt::format("{:.1f}%", 100 * accuracy.get<double>());
  return fmt::format("{} / {:.1f} ms", percent, result.at("median_ms").get<double>());
}

std::string RatioCell(const nlohmann::json& ratio) {
  return ratio.is_null() ? "-" : fmt::format("{:.1f}x", ratio.get<double>());
}

}  // namespace

std::string FormatClusteringTable(const nlohmann::json& report) {
  try {
    // Cells first, then column widths from the widest cell, so long set names stay aligned.
    std::vector<std::vector<std::string>> rows = {{"method \\ set (accuracy / ms)"}};
    for (const nlohmann::json& set : report.at("sets")) {
      rows[0].push_back(fmt::format("{} ({} pts, K={})", set.at("name").get<std::string>(),
                                    set.at("points").get<size_t>(), set.at("clusters").get<int>()));
    }
    std::string notes;
    for (const nlohmann::json& method : report.at("methods")) {
      const std::string name = method.at("name");
      rows.push_back({name});
      for (const nlohmann::json& result : method.at("results")) {
        rows.back().push_back(Cell(result));
        if (result.contains("reason")) {
          notes += fmt::format("  {} on {}: {} ({})\n", name, result.at("set").get<std::string>(),
                               result.at("status").get<std::string>(),
                               result.at("reason").get<std::string>());
        }
      }
    }
    const std::pair<const char*, const char*> ratio_rows[] = {
        {"dense_spectral_over_ours", "time dense spectral / ours"},
        {"sparse_spectral_over_ours", "time sparse spectral / ours"}};
    for (const auto& [key, label] : ratio_rows) {
      rows.push_back({label});
      for (const nlohmann::json& ratio : report.at("speed_ratios")) {
        rows.back().push_back(RatioCell(ratio.at(key)));
      }
    }
    std::vector<size_t> widths;
    for (const std::vector<std::string>& row : rows) {
      widths.resize(std::max(widths.size(), row.size()), 0);
      for (size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
    }
    std::string text;
    for (const std::vector<std::string>& row : rows) {
      for (size_t c = 0; c < row.size(); ++c) {
        text += c == 0 ? fmt::format("{:<{}}", row[c], widths[c])
                       : fmt::format("  {:>{}}", row[c], widths[c]);
      }
      text += "\n";
    }
    return notes.empty() ? text : text + "notes:\n" + notes;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("FormatClusteringTable: malformed report: ") +
                                e.what());
  }
}

}  // namespace avc::bench
