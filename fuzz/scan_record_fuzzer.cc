// A scan directory's scan.json as `avc scan --resume` reads it (orchestrator::LoadScanRecord).

#include <cstdint>
#include <stdexcept>

#include "orchestrator/scan_record.h"

#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto dir = avc::fuzz::FreshDir("scan");
  avc::fuzz::WriteFile(dir, "scan.json", avc::fuzz::AsText(data, size));
  try {
    avc::orchestrator::LoadScanRecord(dir);
  } catch (const std::runtime_error&) {  // names the file and the bad field
  }
  return 0;
}
