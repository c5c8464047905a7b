#include "core/messages/mvs_points_message.h"

#include <fmt/format.h>

#include <stdexcept>

#include "core/messages/point_records.h"

namespace avc::messages {
namespace {

// 6 floats, 3 colour bytes, a pad byte, the confidence: 32 bytes.
const std::vector<FieldSpec>& MvsFields() {
  static const std::vector<FieldSpec> fields = {
      {"x", kFloat},  {"y", kFloat},  {"z", kFloat},    {"nx", kFloat},  {"ny", kFloat},
      {"nz", kFloat}, {"red", kByte}, {"green", kByte}, {"blue", kByte}, {"confidence", kFloat}};
  return fields;
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
  message.points = MakePointCloud(cloud_id, MvsFields(), points.size());
  avc::point_cloud_t& cloud = message.points;
  const std::string what = fmt::format("MVS points '{}'", cloud_id);
  const int32_t colour = FieldOffset(cloud, {"red"}, kByte, what);
  const int32_t confidence = FieldOffset(cloud, {"confidence"}, kFloat, what);

  for (size_t i = 0; i < points.size(); ++i) {
    uint8_t* record = cloud.data.data() + i * static_cast<size_t>(cloud.point_step);
    for (int a = 0; a < 3; ++a) {
      PutFloat(record + 4 * a, points.cloud.positions[i][a]);
      PutFloat(record + 12 + 4 * a, points.cloud.normals[i][a]);
      record[colour + a] = points.cloud.colors[i][a];
    }
    PutFloat(record + confidence, points.confidence[i]);

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
  const std::string what = fmt::format("MVS points '{}'", id);
  CheckPointCloud(cloud, what);
  if (message.num_images != static_cast<int32_t>(message.image_ids.size()) ||
      message.views_size != static_cast<int32_t>(message.views.size())) {
    throw std::invalid_argument(
        fmt::format("MVS points '{}': num_images or views_size disagrees with its array", id));
  }
  const int32_t position[3] = {FieldOffset(cloud, {"x"}, kFloat, what),
                               FieldOffset(cloud, {"y"}, kFloat, what),
                               FieldOffset(cloud, {"z"}, kFloat, what)};
  const int32_t normal[3] = {FieldOffset(cloud, {"nx"}, kFloat, what),
                             FieldOffset(cloud, {"ny"}, kFloat, what),
                             FieldOffset(cloud, {"nz"}, kFloat, what)};
  const int32_t colour[3] = {FieldOffset(cloud, {"red", "r"}, kByte, what),
                             FieldOffset(cloud, {"green", "g"}, kByte, what),
                             FieldOffset(cloud, {"blue", "b"}, kByte, what)};
  const int32_t confidence = FieldOffset(cloud, {"confidence"}, kFloat, what);

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

}  // namespace avc::messages
