#include "sim/emulators/ptpip/ptp_object_store.h"

#include <fmt/format.h>

#include <stdexcept>

#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim::ptp {
namespace {

constexpr uint64_t kCapacityBytes = uint64_t{32} << 30;  // a 32 GB card

}  // namespace

uint32_t ObjectStore::Add(EmulatedFrame frame) {
  if (frame.data.empty()) throw std::invalid_argument("PTP/IP camera: frame source gave no bytes");
  if (frame.object_format != kFormatExifJpeg && frame.object_format != kFormatPng) {
    throw std::invalid_argument(fmt::format(
        "PTP/IP camera: frame format 0x{:04x} is neither JPEG (0x3801) nor PNG (0x380b)",
        frame.object_format));
  }
  if (frame.file_name.empty()) {
    throw std::invalid_argument("PTP/IP camera: frame source gave no file name");
  }
  if (frame.data.size() > 0xFFFFFFFFu) {
    throw std::invalid_argument(
        fmt::format("PTP/IP camera: frame of {} bytes exceeds PTP's 4 GiB", frame.data.size()));
  }
  StoredObject object;
  object.info.storage_id = kStorageId;
  object.info.object_format = frame.object_format;
  object.info.compressed_size = static_cast<uint32_t>(frame.data.size());
  object.info.image_width = frame.width;
  object.info.image_height = frame.height;
  object.info.image_bit_depth = frame.width > 0 ? 24 : 0;
  object.info.filename = std::move(frame.file_name);
  object.data = std::move(frame.data);
  const uint32_t handle = next_handle_++;
  objects_.emplace(handle, std::move(object));
  return handle;
}

const StoredObject* ObjectStore::Find(uint32_t handle) const {
  const auto it = objects_.find(handle);
  return it == objects_.end() ? nullptr : &it->second;
}

bool ObjectStore::Remove(uint32_t handle) { return objects_.erase(handle) > 0; }

void ObjectStore::Clear() { objects_.clear(); }

std::vector<uint32_t> ObjectStore::Handles() const {
  std::vector<uint32_t> handles;
  for (const auto& [handle, object] : objects_) handles.push_back(handle);
  return handles;
}

StorageInfo ObjectStore::Info() const {
  uint64_t used = 0;
  for (const auto& [handle, object] : objects_) used += object.data.size();
  StorageInfo info;
  info.storage_type = kStorageRemovableRam;
  info.filesystem_type = kFilesystemGenericHierarchical;
  info.access_capability = kAccessReadWrite;
  info.max_capacity = kCapacityBytes;
  info.free_space_bytes = kCapacityBytes - used;
  info.free_space_images = 0xFFFFFFFF;  // "not used" per PTP
  info.description = "Emulated SD card";
  info.volume_label = "AVC";
  return info;
}

}  // namespace avc::sim::ptp
