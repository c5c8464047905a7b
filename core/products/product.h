#pragma once

// A product: one encoded AVC message (image_t, point_cloud_t, mesh_t, voxel_map_t, ...) that
// travels reliably on the bulk URL as product_chunk_t messages.

#include <cstdint>
#include <string>
#include <vector>

namespace avc::products {

struct Product {
  std::string product_id;    // unique per producer incarnation
  std::string name;          // file-like name, e.g. "images/view_0012.png"
  std::string content_type;  // LCM type of the payload, e.g. "avc.image_t"
  std::string sha256;        // of payload
  std::string source;        // producer (header.source of its chunks)
  int64_t utime = 0;         // header.utime of the first chunk sent
  std::vector<uint8_t> payload;
};

// The content_type string for a generated LCM type: "avc.image_t".
template <class T>
std::string ContentTypeOf() {
  return std::string("avc.") + T::getTypeName();
}

}  // namespace avc::products
