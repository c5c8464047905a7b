#include "services/builder/node_mvs_message.h"

#include <fmt/format.h>

#include <avc/point_field_t.hpp>
#include <bit>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace avc::builder {
namespace {

// The record this side writes: 6 floats, 3 colour bytes, one pad byte, the confidence.
constexpr int32_t kPointStep = 32;
constexpr int32_t kColourOffset = 24;
constexpr int32_t kConfidenceOffset = 28;

void PutFloat(uint8_t* out, float value) {
  const uint32_t bits = std::bit_cast<uint32_t>(value);
  for (int i = 0; i < 4; ++i) out[i] = static_cast<uint8_t>(bits >> (8 * i));
}

float GetFloat(const uint8_t* in) {
  uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) bits |= static_cast<uint32_t>(in[i]) << (8 * i);
  return std::bit_cast<float>(bits);
}

avc::point_field_t Field(const std::string& name, int32_t offset, int8_t datatype) {
  avc::point_field_t field{};
  field.name = name;
  field.offset = offset;
  field.datatype = datatype;
  field.count = 1;
  return field;
}

int FieldBytes(int8_t datatype) { return datatype == avc::point_field_t::TYPE_FLOAT32 ? 4 : 1; }

// The offset of the field called one of `names`, checked against the record.
int32_t FindField(const avc::point_cloud_t& cloud, std::initializer_list<const char*> names,
                  int8_t datatype) {
  for (const avc::point_field_t& field : cloud.fields) {
    bool matches = false;
    for (const char* name : names) matches = matches || field.name == name;
    if (!matches) continue;
    if (field.datatype != datatype || field.count != 1) {
      throw std::invalid_argument(
          fmt::format("MVS points '{}': field '{}' has datatype {} x {}, expected {} x 1",
                      cloud.cloud_id, field.name, field.datatype, field.count, datatype));
    }
    if (field.offset < 0 || field.offset + FieldBytes(datatype) > cloud.point_step) {
      throw std::invalid_argument(
          fmt::format("MVS points '{}': field '{}' at offset {} leaves the {}-byte record",
                      cloud.cloud_id, field.name, field.offset, cloud.point_step));
    }
    return field.offset;
  }
  throw std::invalid_argument(
      fmt::format("MVS points '{}': no field '{}'", cloud.cloud_id, *names.begin()));
}

}  // namespace

avc::mvs_points_t MvsPointsToMessage(const mvs::MvsPoints& points,
                                     const std::vector<std::string>& image_ids,
                                     const std::string& cloud_id) {
  if (const std::string problem = points.Validate(); !problem.empty()) {
    throw std::invalid_argument(fmt::format("MVS points '{}': {}", cloud_id, problem));
  }
  if (image_ids.size() > 65536) {
    throw std::invalid_argument(fmt::format(
        "MVS points '{}': {} images do not fit 16-bit view indices", cloud_id, image_ids.size()));
  }
  avc::mvs_points_t message{};
  message.cloud_id = cloud_id;
  avc::point_cloud_t& cloud = message.points;
  cloud.cloud_id = cloud_id;
  cloud.frame = "world";
  const char* axes[] = {"x", "y", "z", "nx", "ny", "nz"};
  for (int i = 0; i < 6; ++i) {
    cloud.fields.push_back(Field(axes[i], 4 * i, avc::point_field_t::TYPE_FLOAT32));
  }
  const char* colours[] = {"red", "green", "blue"};
  for (int i = 0; i < 3; ++i) {
    cloud.fields.push_back(Field(colours[i], kColourOffset + i, avc::point_field_t::TYPE_UINT8));
  }
  cloud.fields.push_back(Field("confidence", kConfidenceOffset, avc::point_field_t::TYPE_FLOAT32));
  cloud.num_fields = static_cast<int32_t>(cloud.fields.size());
  cloud.point_step = kPointStep;
  cloud.num_points = static_cast<int32_t>(points.size());
  cloud.data.assign(points.size() * kPointStep, 0);
  cloud.data_size = static_cast<int32_t>(cloud.data.size());

  for (size_t i = 0; i < points.size(); ++i) {
    uint8_t* record = cloud.data.data() + i * kPointStep;
    for (int a = 0; a < 3; ++a) {
      PutFloat(record + 4 * a, points.cloud.positions[i][a]);
      PutFloat(record + 12 + 4 * a, points.cloud.normals[i][a]);
      record[kColourOffset + a] = points.cloud.colors[i][a];
    }
    PutFloat(record + kConfidenceOffset, points.confidence[i]);

    const std::vector<uint32_t>& views = points.views[i];
    if (views.size() > 255) {
      throw std::invalid_argument(fmt::format("MVS points '{}': point {} has {} views, at most 255",
                                              cloud_id, i, views.size()));
    }
    message.views.push_back(static_cast<uint8_t>(views.size()));
    for (const uint32_t view : views) {
      if (view >= image_ids.size()) {
        throw std::invalid_argument(
            fmt::format("MVS points '{}': point {} refers to image {} of {}", cloud_id, i, view,
                        image_ids.size()));
      }
      message.views.push_back(static_cast<uint8_t>(view & 0xff));
      message.views.push_back(static_cast<uint8_t>(view >> 8));
    }
  }
  message.views_size = static_cast<int32_t>(message.views.size());
  message.image_ids = image_ids;
  message.num_images = static_cast<int32_t>(image_ids.size());
  return message;
}

MvsPointsMessageContent MvsPointsFromMessage(const avc::mvs_points_t& message) {
  const avc::point_cloud_t& cloud = message.points;
  const std::string& id = message.cloud_id;
  if (cloud.num_points < 0 || cloud.point_step <= 0 ||
      static_cast<int64_t>(cloud.num_points) * cloud.point_step != cloud.data_size ||
      cloud.data_size != static_cast<int64_t>(cloud.data.size()) ||
      cloud.num_fields != static_cast<int32_t>(cloud.fields.size())) {
    throw std::invalid_argument(
        fmt::format("MVS points '{}': {} points x {} bytes do not match {} data bytes", id,
                    cloud.num_points, cloud.point_step, cloud.data.size()));
  }
  if (message.num_images != static_cast<int32_t>(message.image_ids.size()) ||
      message.views_size != static_cast<int32_t>(message.views.size())) {
    throw std::invalid_argument(
        fmt::format("MVS points '{}': num_images or views_size disagrees with its array", id));
  }
  constexpr int8_t kFloat = avc::point_field_t::TYPE_FLOAT32;
  constexpr int8_t kByte = avc::point_field_t::TYPE_UINT8;
  const int32_t position[3] = {FindField(cloud, {"x"}, kFloat), FindField(cloud, {"y"}, kFloat),
                               FindField(cloud, {"z"}, kFloat)};
  const int32_t normal[3] = {FindField(cloud, {"nx"}, kFloat), FindField(cloud, {"ny"}, kFloat),
                             FindField(cloud, {"nz"}, kFloat)};
  const int32_t colour[3] = {FindField(cloud, {"red", "r"}, kByte),
                             FindField(cloud, {"green", "g"}, kByte),
                             FindField(cloud, {"blue", "b"}, kByte)};
  const int32_t confidence = FindField(cloud, {"confidence"}, kFloat);

  MvsPointsMessageContent content;
  content.image_ids = message.image_ids;
  mvs::MvsPoints& points = content.points;
  const size_t n = static_cast<size_t>(cloud.num_points);
  points.cloud.positions.resize(n);
  points.cloud.normals.resize(n);
  points.cloud.colors.resize(n);
  points.confidence.resize(n);
  points.views.resize(n);
  size_t cursor = 0;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* record = cloud.data.data() + i * static_cast<size_t>(cloud.point_step);
    for (int a = 0; a < 3; ++a) {
      points.cloud.positions[i][a] = GetFloat(record + position[a]);
      points.cloud.normals[i][a] = GetFloat(record + normal[a]);
      points.cloud.colors[i][a] = record[colour[a]];
    }
    points.confidence[i] = GetFloat(record + confidence);

    if (cursor >= message.views.size()) {
      throw std::invalid_argument(
          fmt::format("MVS points '{}': the view lists end before point {}", id, i));
    }
    const size_t count = message.views[cursor++];
    if (cursor + 2 * count > message.views.size()) {
      throw std::invalid_argument(
          fmt::format("MVS points '{}': point {}'s view list runs past the end", id, i));
    }
    points.views[i].resize(count);
    for (size_t v = 0; v < count; ++v, cursor += 2) {
      const uint32_t index = message.views[cursor] | (message.views[cursor + 1] << 8);
      if (index >= message.image_ids.size()) {
        throw std::invalid_argument(
            fmt::format("MVS points '{}': point {} refers to image {} of {}", id, i, index,
                        message.image_ids.size()));
      }
      points.views[i][v] = index;
    }
  }
  if (cursor != message.views.size()) {
    throw std::invalid_argument(fmt::format("MVS points '{}': {} bytes of view lists left over", id,
                                            message.views.size() - cursor));
  }
  if (const std::string problem = points.Validate(); !problem.empty()) {
    throw std::invalid_argument(fmt::format("MVS points '{}': {}", id, problem));
  }
  return content;
}

}  // namespace avc::builder
