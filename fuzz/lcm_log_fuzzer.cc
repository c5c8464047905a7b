// An LCM log as `avc replay` reads it: record::LogReader (which parses damaged logs itself) to
// the end, where damage is never an exception, then the log's cell from its RUN_INFO event
// (record::CellOfLog), which refuses with ReplayError.

#include <cstdint>

#include "core/record/log_reader.h"
#include "core/record/replay.h"

#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path =
      avc::fuzz::WriteFile(avc::fuzz::TempDir(), "fuzz.lcmlog", avc::fuzz::AsText(data, size));
  avc::record::LogReader reader(path);
  while (reader.Next() != nullptr) {
  }
  try {
    avc::record::CellOfLog(path);
  } catch (const avc::record::ReplayError&) {
  }
  return 0;
}
