// A launch file as `avc up` reads it (launch::ParseLaunchFile): the first byte picks the format
// ('0' TOML, '1' YAML by its lowest bit), the rest is the text.

#include <cstdint>

#include "core/launch/launch_file.h"

#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string file = (data[0] & 1) != 0 ? "/avc-fuzz/cell.yaml" : "/avc-fuzz/cell.toml";
  try {
    avc::launch::ParseLaunchFile(avc::fuzz::AsText(data + 1, size - 1), file);
  } catch (const avc::launch::LaunchFileError&) {  // "<file>:<line>: <problem>"
  }
  return 0;
}
