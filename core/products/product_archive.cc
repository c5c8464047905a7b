#include "core/products/product_archive.h"

#include <fmt/format.h>

#include <avc/image_t.hpp>
#include <avc/mesh_t.hpp>
#include <avc/point_cloud_t.hpp>
#include <avc/voxel_map_t.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/bus/decode.h"
#include "core/products/point_cloud_ply.h"
#include "core/util/log.h"

namespace avc::products {
namespace {

template <class T>
T DecodeAs(const Product& product) {
  T msg;
  if (!bus::DecodeMessage(product.payload.data(), product.payload.size(), &msg)) {
    throw std::invalid_argument(
        fmt::format("product '{}' does not decode as {}", product.name, product.content_type));
  }
  return msg;
}

std::filesystem::path SafeRelativePath(const std::string& name) {
  const std::filesystem::path path(name);
  if (name.empty() || path.is_absolute()) {
    throw std::invalid_argument("product name '" + name + "' must be a relative path");
  }
  for (const auto& part : path) {
    if (part == "..") throw std::invalid_argument("product name '" + name + "' contains '..'");
  }
  return path.lexically_normal();
}

std::filesystem::path WithExtension(std::filesystem::path path, const char* extension) {
  if (path.extension().empty()) path += extension;
  return path;
}

std::string Bytes(const std::vector<uint8_t>& data) {
  return std::string(data.begin(), data.end());
}

StoredFile ImageFile(const std::filesystem::path& path, const avc::image_t& image) {
  switch (image.encoding) {
    case avc::image_t::ENCODING_PNG:
      return {WithExtension(path, ".png"), Bytes(image.data)};
    case avc::image_t::ENCODING_JPEG:
      return {WithExtension(path, ".jpg"), Bytes(image.data)};
    default:
      break;
  }
  // Raw 8-bit images become PGM/PPM: viewable anywhere, no codec, exact bytes.
  const bool gray = image.pixel_format == avc::image_t::PIXEL_GRAY8;
  const bool rgb = image.pixel_format == avc::image_t::PIXEL_RGB8;
  const int channels = gray ? 1 : 3;
  const int64_t row_bytes = static_cast<int64_t>(image.width) * channels;
  const int64_t stride = image.row_stride > 0 ? image.row_stride : row_bytes;
  if ((gray || rgb) && image.width > 0 && image.height > 0 && stride >= row_bytes &&
      stride * image.height <= static_cast<int64_t>(image.data.size())) {
    std::string out = fmt::format("P{}\n{} {}\n255\n", gray ? 5 : 6, image.width, image.height);
    for (int64_t y = 0; y < image.height; ++y) {
      out.append(reinterpret_cast<const char*>(image.data.data() + y * stride),
                 static_cast<size_t>(row_bytes));
    }
    return {WithExtension(path, gray ? ".pgm" : ".ppm"), std::move(out)};
  }
  return {};
}

}  // namespace

StoredFile ToStoredFile(const Product& product) {
  const std::filesystem::path path = SafeRelativePath(product.name);
  if (product.content_type == "avc.image_t") {
    StoredFile file = ImageFile(path, DecodeAs<avc::image_t>(product));
    if (!file.relative_path.empty()) return file;
  } else if (product.content_type == "avc.mesh_t") {
    return {WithExtension(path, ".ply"), Bytes(DecodeAs<avc::mesh_t>(product).data)};
  } else if (product.content_type == "avc.voxel_map_t") {
    const avc::voxel_map_t map = DecodeAs<avc::voxel_map_t>(product);
    return {
        WithExtension(path, map.encoding == avc::voxel_map_t::ENCODING_OCTOMAP_OT ? ".ot" : ".bt"),
        Bytes(map.data)};
  } else if (product.content_type == "avc.point_cloud_t") {
    return {WithExtension(path, ".ply"), PointCloudToPly(DecodeAs<avc::point_cloud_t>(product))};
  }
  return {WithExtension(path, ".lcm"), Bytes(product.payload)};
}

ProductArchive::ProductArchive(bus::Bus& bus, std::filesystem::path dir, std::string receiver_name)
    : dir_(std::move(dir)),
      receiver_(bus, std::move(receiver_name), "PRODUCT/.*",
                [this](const Product& product, const bus::RxInfo&) { Store(product); }) {
  std::filesystem::create_directories(dir_);
}

void ProductArchive::Store(const Product& product) {
  StoredFile file;
  try {
    file = ToStoredFile(product);
  } catch (const std::invalid_argument& e) {
    // A product that can never be stored is reported and skipped; retransmitting cannot help.
    log::Error("archive {}: {}", dir_.string(), e.what());
    return;
  }
  const std::filesystem::path target = dir_ / file.relative_path;
  std::filesystem::create_directories(target.parent_path());
  // Write then rename, so a crash never leaves a half-written file under the final name.
  const std::filesystem::path partial = target.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(file.bytes.data(), static_cast<std::streamsize>(file.bytes.size()));
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + partial.string());
  }
  std::filesystem::rename(partial, target);
  nlohmann::json line = {{"file", file.relative_path.string()},  {"name", product.name},
                         {"content_type", product.content_type}, {"sha256", product.sha256},
                         {"bytes", product.payload.size()},      {"source", product.source}};
  std::ofstream manifest(dir_ / "manifest.jsonl", std::ios::app);
  manifest << line.dump() << "\n";
  if (!manifest) throw std::runtime_error("cannot append to " + (dir_ / "manifest.jsonl").string());
  ++stored_;
}

}  // namespace avc::products
