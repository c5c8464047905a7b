#pragma once

// The emulated memory card: one storage holding captured images flat in its root. Handles count
// up from 1 and are never reused, so a stale handle is an error rather than another image.

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "sim/emulators/ptpip/emulated_capture.h"
#include "sim/emulators/ptpip/ptp_datasets.h"

namespace avc::sim::ptp {

inline constexpr uint32_t kStorageId = 0x00010001;

struct StoredObject {
  ObjectInfo info;
  std::vector<uint8_t> data;
};

class ObjectStore {
 public:
  // Throws std::invalid_argument for an empty image, an unknown format or a missing file name.
  uint32_t Add(EmulatedFrame frame);
  const StoredObject* Find(uint32_t handle) const;
  bool Remove(uint32_t handle);
  void Clear();
  std::vector<uint32_t> Handles() const;
  size_t size() const { return objects_.size(); }
  StorageInfo Info() const;

 private:
  std::map<uint32_t, StoredObject> objects_;
  uint32_t next_handle_ = 1;
};

}  // namespace avc::sim::ptp
