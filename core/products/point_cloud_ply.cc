#include "core/products/point_cloud_ply.h"

#include <fmt/format.h>

#include <algorithm>
#include <avc/point_field_t.hpp>
#include <stdexcept>
#include <vector>

namespace avc::products {
namespace {

struct PlyType {
  const char* name;
  int bytes;
};

PlyType ToPlyType(int8_t datatype) {
  switch (datatype) {
    case avc::point_field_t::TYPE_INT8:
      return {"char", 1};
    case avc::point_field_t::TYPE_UINT8:
      return {"uchar", 1};
    case avc::point_field_t::TYPE_INT16:
      return {"short", 2};
    case avc::point_field_t::TYPE_UINT16:
      return {"ushort", 2};
    case avc::point_field_t::TYPE_INT32:
      return {"int", 4};
    case avc::point_field_t::TYPE_UINT32:
      return {"uint", 4};
    case avc::point_field_t::TYPE_FLOAT32:
      return {"float", 4};
    case avc::point_field_t::TYPE_FLOAT64:
      return {"double", 8};
    default:
      throw std::invalid_argument(fmt::format("unknown point field datatype {}", datatype));
  }
}

}  // namespace

std::string PointCloudToPly(const avc::point_cloud_t& cloud) {
  // Each byte of a record becomes at least one header line (padding included): an empty cloud
  // claiming a 2 GB record would write billions of them (fuzz/lcm_messages, a 60-byte message).
  constexpr int32_t kMaxPointStep = 4096;
  if (cloud.point_step > kMaxPointStep) {
    throw std::invalid_argument(fmt::format("point cloud '{}': {}-byte points (at most {})",
                                            cloud.cloud_id, cloud.point_step, kMaxPointStep));
  }
  if (cloud.num_points < 0 || cloud.point_step <= 0 ||
      static_cast<int64_t>(cloud.num_points) * cloud.point_step != cloud.data_size ||
      cloud.data_size != static_cast<int32_t>(cloud.data.size())) {
    throw std::invalid_argument(
        fmt::format("point cloud '{}': {} points x {} bytes does not match {} data bytes",
                    cloud.cloud_id, cloud.num_points, cloud.point_step, cloud.data.size()));
  }
  std::vector<avc::point_field_t> fields = cloud.fields;
  std::sort(fields.begin(), fields.end(),
            [](const auto& a, const auto& b) { return a.offset < b.offset; });
  std::string header =
      fmt::format("ply\nformat binary_little_endian 1.0\ncomment {}\nelement vertex {}\n",
                  cloud.frame.empty() ? "frame world" : "frame " + cloud.frame, cloud.num_points);
  int32_t position = 0;
  int padding = 0;
  auto pad_to = [&](int32_t offset) {
    for (; position < offset; ++position)
      header += fmt::format("property uchar pad{}\n", padding++);
  };
  for (const avc::point_field_t& field : fields) {
    const PlyType type = ToPlyType(field.datatype);
    if (field.offset < position || field.count < 1 ||
        // In 64 bits: a hostile count times the type's size overflows int (fuzz/lcm_messages).
        int64_t{field.offset} + int64_t{field.count} * type.bytes > cloud.point_step) {
      throw std::invalid_argument(
          fmt::format("point cloud '{}': field '{}' overlaps another or "
                      "leaves the {}-byte record",
                      cloud.cloud_id, field.name, cloud.point_step));
    }
    pad_to(field.offset);
    for (int32_t i = 0; i < field.count; ++i) {
      header += field.count == 1 ? fmt::format("property {} {}\n", type.name, field.name)
                                 : fmt::format("property {} {}{}\n", type.name, field.name, i);
    }
    position = field.offset + field.count * type.bytes;
  }
  pad_to(cloud.point_step);
  header += "end_header\n";
  header.append(cloud.data.begin(), cloud.data.end());
  return header;
}

}  // namespace avc::products
