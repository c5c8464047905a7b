// A OFF file read as a mesh (geometry::ReadMesh) and as a point cloud (geometry::ReadPointCloud).

#include <cstdint>

#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  avc::fuzz::ReadMeshFile("fuzz.off", data, size);
  return 0;
}
