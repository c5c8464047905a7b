#include "tools/avc/builder_flags.h"

#include <fmt/format.h>

#include "core/config/option_text.h"

namespace avc::cli {

std::vector<std::string> BuilderShorthands::Settings(const std::vector<std::string>& sets) const {
  std::vector<std::string> settings;
  if (method) settings.push_back("method=" + *method);
  if (masks) settings.push_back("masks.method=" + *masks);
  if (level) {
    settings.push_back(fmt::format("patch.level={}", *level));
    settings.push_back(fmt::format("sweep.level={}", *level));
  }
  if (tolerance) settings.push_back(fmt::format("proxy.background_votes_allowed={}", *tolerance));
  if (voxel_mm) settings.push_back("proxy.final_voxel_size=" + config::RealText(*voxel_mm * 1e-3));
  settings.insert(settings.end(), sets.begin(), sets.end());
  return settings;
}

void AddBuilderShorthands(CLI::App* command, BuilderShorthands* flags,
                          const std::string& method_flag) {
  command->add_option(method_flag, flags->method,
                      "multi-view stereo: patch (PMVS-style), plane-sweep or none (method)");
  command->add_option("--level", flags->level,
                      "MVS image pyramid level, 0 full size, 1 half, -1 automatic (patch.level "
                      "and sweep.level)");
  command->add_option("--tolerance", flags->tolerance,
                      "background votes a proxy voxel survives (proxy.background_votes_allowed)");
  command->add_option("--voxel-mm", flags->voxel_mm,
                      "final proxy voxel size in mm; 0 from the scene's size "
                      "(proxy.final_voxel_size, in m)");
}

}  // namespace avc::cli
