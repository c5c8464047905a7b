// One LCM message as a process receives it: the bytes are decoded as the type whose fingerprint
// they start with (as a subscriber on that type's channel would), then handed to the codec the
// receiving service applies to that type. Types without a codec stop at the LCM decode.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/bus/decode.h"
#include "core/messages/camera_message.h"
#include "core/messages/clusters_message.h"
#include "core/messages/mesh_message.h"
#include "core/messages/mvs_points_message.h"
#include "core/messages/point_records.h"
#include "core/ppr/octree_voxels.h"
#include "core/products/chunking.h"
#include "core/products/point_cloud_ply.h"
#include "core/products/product_archive.h"
#include "services/builder/node_inputs.h"

#include "fuzz/fuzz_support.h"
#include "fuzz/lcm_types.inc"

namespace avc {
namespace {

// The collector (avc collect) stores image, mesh, voxel map and point cloud products as files.
template <class T>
void Archive(const uint8_t* data, size_t size) {
  products::Product product;
  product.name = "fuzz/product";
  product.content_type = products::ContentTypeOf<T>();
  product.payload.assign(data, data + size);
  products::ToStoredFile(product);
}

template <class T>
void Interpret(const T&, const uint8_t*, size_t) {}

void Interpret(const avc::camera_t& message, const uint8_t*, size_t) {  // builder, planner
  messages::CameraFromMessage(message);
}
void Interpret(const avc::clusters_t& message, const uint8_t*, size_t) {  // surfacer
  messages::ClustersFromMessage(message);
}
void Interpret(const avc::mvs_points_t& message, const uint8_t*, size_t) {  // clusterer
  messages::MvsPointsFromMessage(message);
}
void Interpret(const avc::image_t& message, const uint8_t* data, size_t size) {  // builder
  Archive<avc::image_t>(data, size);
  builder::DecodeImage(message);
}
void Interpret(const avc::mesh_t& message, const uint8_t* data, size_t size) {
  Archive<avc::mesh_t>(data, size);
  messages::MeshFromMessage(message);
}
void Interpret(const avc::point_cloud_t& message, const uint8_t* data, size_t size) {
  Archive<avc::point_cloud_t>(data, size);
  messages::CheckPointCloud(message, "point cloud");
  products::PointCloudToPly(message);
}
void Interpret(const avc::voxel_map_t& message, const uint8_t* data, size_t size) {  // clusterer
  Archive<avc::voxel_map_t>(data, size);
  if (message.encoding != avc::voxel_map_t::ENCODING_OCTOMAP_BT) return;
  ppr::OccupiedVoxelsFromBinary(std::string(message.data.begin(), message.data.end()),
                                message.resolution, "voxel map",
                                {.max_voxels = fuzz::kFuzzMaxVoxels});
}
void Interpret(const avc::product_chunk_t& message, const uint8_t*, size_t) {  // every receiver
  products::Reassembler reassembler;
  const products::Reassembler::Outcome outcome = reassembler.Add(message);
  if (outcome.product) products::ToStoredFile(*outcome.product);
}

// True when the bytes carry T's fingerprint (they then belong to no other type).
template <class T>
bool TryType(int64_t fingerprint, const uint8_t* data, size_t size) {
  if (fingerprint != T::getHash()) return false;
  T message;
  if (!bus::DecodeMessage(data, size, &message)) return true;  // as every subscriber decodes
  try {
    Interpret(message, data, size);
  } catch (const std::invalid_argument&) {  // the codecs' documented refusal
  }
  return true;
}

}  // namespace
}  // namespace avc

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 8 || size > (1u << 28)) return 0;  // no fingerprint / over LCM's message limit
  uint64_t bits = 0;                            // big-endian, as LCM encodes it
  for (int i = 0; i < 8; ++i) bits = (bits << 8) | data[i];
  const auto fingerprint = static_cast<int64_t>(bits);
#define AVC_FUZZ_LCM_TYPE(type) avc::TryType<avc::type>(fingerprint, data, size) ||
  static_cast<void>(AVC_FUZZ_ALL_LCM_TYPES false);
#undef AVC_FUZZ_LCM_TYPE
  return 0;
}
