#pragma once

// Stores every product received on "PRODUCT/.*" in a directory, as files people can open:
// images as their PNG/JPEG (raw 8-bit images as PGM/PPM), meshes as PLY, voxel maps as OctoMap
// .bt/.ot, point clouds as binary PLY, anything else as the encoded LCM message (.lcm). Each
// stored product appends one line to manifest.jsonl. Output depends only on the products and
// their order, so replaying a log twice gives identical trees.

#include <filesystem>
#include <string>

#include "core/bus/bus.h"
#include "core/products/product_receiver.h"

namespace avc::products {

class ProductArchive {
 public:
  ProductArchive(bus::Bus& bus, std::filesystem::path dir, std::string receiver_name = "archive");

  const std::filesystem::path& dir() const { return dir_; }
  int64_t stored() const { return stored_; }
  const ReceiverStats& receiver_stats() const { return receiver_.stats(); }

 private:
  void Store(const Product& product);

  std::filesystem::path dir_;
  int64_t stored_ = 0;
  ProductReceiver receiver_;
};

// The file name and bytes a product is stored as (pure, for tests and other writers). Throws
// std::invalid_argument if the product's name would leave the archive (absolute, "..") or its
// payload does not decode as its content type.
struct StoredFile {
  std::filesystem::path relative_path;
  std::string bytes;
};
StoredFile ToStoredFile(const Product& product);

}  // namespace avc::products
