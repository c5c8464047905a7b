#include "tools/avc/builder_flags.h"

namespace avc::cli {

void AddBuilderShorthands(CLI::App* command, ConfigFlags* flags, const std::string& method_flag) {
  AddShorthand(command, flags, method_flag, "method",
               "multi-view stereo: patch (PMVS-style), plane-sweep or none");
  AddShorthandForAll(command, flags, "--level", {"patch.level", "sweep.level"},
                     "MVS image pyramid level, 0 full size, 1 half, -1 automatic");
  AddShorthand(command, flags, "--tolerance", "proxy.background_votes_allowed",
               "background votes a proxy voxel survives");
  AddScaledShorthand(command, flags, "--voxel-mm", "proxy.final_voxel_size", 1e-3,
                     "final proxy voxel size in mm; 0 from the scene's size");
}

}  // namespace avc::cli
