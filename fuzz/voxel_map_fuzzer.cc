// The plant proxy as the clusterer receives it: OctoMap binary (.bt) bytes read into occupied
// voxels (ppr::OccupiedVoxelsFromBinary), with the tree's own resolution and with the sender's.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/ppr/octree_voxels.h"

#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(avc::fuzz::AsText(data, size));
  for (const double voxel_size : {0.0, 0.002}) {
    try {
      avc::ppr::OccupiedVoxelsFromBinary(bytes, voxel_size, "voxel map",
                                         {.max_voxels = avc::fuzz::kFuzzMaxVoxels});
    } catch (const std::invalid_argument&) {  // the documented refusal
    }
  }
  return 0;
}
