#include "core/messages/point_records.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::messages {

int DatatypeBytes(int8_t datatype) {
  switch (datatype) {
    case avc::point_field_t::TYPE_INT8:
    case avc::point_field_t::TYPE_UINT8:
      return 1;
    case avc::point_field_t::TYPE_INT16:
    case avc::point_field_t::TYPE_UINT16:
      return 2;
    case avc::point_field_t::TYPE_INT32:
    case avc::point_field_t::TYPE_UINT32:
    case avc::point_field_t::TYPE_FLOAT32:
      return 4;
    case avc::point_field_t::TYPE_FLOAT64:
      return 8;
    default:
      return 0;
  }
}

avc::point_cloud_t MakePointCloud(const std::string& cloud_id, const std::vector<FieldSpec>& fields,
                                  size_t num_points) {
  avc::point_cloud_t cloud{};
  cloud.cloud_id = cloud_id;
  cloud.frame = "world";
  int32_t offset = 0;
  int32_t alignment = 1;
  for (const FieldSpec& spec : fields) {
    const int bytes = DatatypeBytes(spec.datatype);
    if (bytes == 0) {
      throw std::invalid_argument(
          fmt::format("point field '{}': unknown datatype {}", spec.name, spec.datatype));
    }
    offset = (offset + bytes - 1) / bytes * bytes;
    alignment = std::max(alignment, bytes);
    avc::point_field_t field{};
    field.name = spec.name;
    field.offset = offset;
    field.datatype = spec.datatype;
    field.count = 1;
    cloud.fields.push_back(field);
    offset += bytes;
  }
  cloud.num_fields = static_cast<int32_t>(cloud.fields.size());
  cloud.point_step = (offset + alignment - 1) / alignment * alignment;
  if (num_points > static_cast<size_t>(INT32_MAX / std::max(cloud.point_step, 1))) {
    throw std::invalid_argument(
        fmt::format("cloud '{}': {} points do not fit one product", cloud_id, num_points));
  }
  cloud.num_points = static_cast<int32_t>(num_points);
  cloud.data.assign(num_points * static_cast<size_t>(cloud.point_step), 0);
  cloud.data_size = static_cast<int32_t>(cloud.data.size());
  return cloud;
}

void CheckPointCloud(const avc::point_cloud_t& cloud, const std::string& what) {
  if (cloud.num_points < 0 || cloud.point_step <= 0 ||
      static_cast<int64_t>(cloud.num_points) * cloud.point_step != cloud.data_size ||
      cloud.data_size != static_cast<int64_t>(cloud.data.size()) ||
      cloud.num_fields != static_cast<int32_t>(cloud.fields.size())) {
    throw std::invalid_argument(fmt::format("{}: {} points x {} bytes do not match {} data bytes",
                                            what, cloud.num_points, cloud.point_step,
                                            cloud.data.size()));
  }
}

int32_t FieldOffset(const avc::point_cloud_t& cloud, std::initializer_list<const char*> names,
                    int8_t datatype, const std::string& what) {
  for (const avc::point_field_t& field : cloud.fields) {
    bool matches = false;
    for (const char* name : names) matches = matches || field.name == name;
    if (!matches) continue;
    if (field.datatype != datatype || field.count != 1) {
      throw std::invalid_argument(
          fmt::format("{}: field '{}' has datatype {} x {}, expected {} x 1", what, field.name,
                      field.datatype, field.count, datatype));
    }
    if (field.offset < 0 || field.offset + DatatypeBytes(datatype) > cloud.point_step) {
      throw std::invalid_argument(
          fmt::format("{}: field '{}' at offset {} leaves the {}-byte record", what, field.name,
                      field.offset, cloud.point_step));
    }
    return field.offset;
  }
  throw std::invalid_argument(fmt::format("{}: no field '{}'", what, *names.begin()));
}

}  // namespace avc::messages
