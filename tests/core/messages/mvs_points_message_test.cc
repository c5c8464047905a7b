// MVS points on the bus: the mvs_points_t round trip is exact through LCM bytes, the record is a
// point cloud PointCloudToPly can write, other layouts read by field name, and every malformed
// message is refused with a message naming the field or point.

#include "core/messages/mvs_points_message.h"

#include <gtest/gtest.h>

#include <avc/point_field_t.hpp>
#include <random>

#include "core/products/point_cloud_ply.h"
#include "tests/support/test_support.h"

namespace avc::messages {
namespace {

// Values from raw generator bits, so the points are the same with any standard library.
float Unit(std::mt19937& rng) {
  return static_cast<float>(rng() >> 8) / static_cast<float>(1 << 24);
}

mvs::MvsPoints RandomPoints(size_t count, uint32_t images, uint32_t seed) {
  std::mt19937 rng(seed);
  mvs::MvsPoints points;
  for (size_t i = 0; i < count; ++i) {
    // One draw per statement: the order of a call's arguments is unspecified.
    Eigen::Vector3f position;
    for (int k = 0; k < 3; ++k) position[k] = Unit(rng) - 0.5f;
    position.z() = (position.z() + 0.5f) * 0.3f;
    points.cloud.positions.push_back(position);
    Eigen::Vector3f normal(0, 0, 1);
    for (int k = 0; k < 2; ++k) normal[k] = Unit(rng) - 0.5f;
    points.cloud.normals.push_back(normal.normalized());
    Eigen::Matrix<uint8_t, 3, 1> colour;
    for (int k = 0; k < 3; ++k) colour[k] = static_cast<uint8_t>(rng());
    points.cloud.colors.push_back(colour);
    points.confidence.push_back(Unit(rng));
    std::vector<uint32_t> views;
    for (uint32_t v = 0; v < images; ++v) {
      if (rng() % 3 == 0) views.push_back(v);
    }
    points.views.push_back(views);
  }
  return points;
}

std::vector<std::string> ImageIds(size_t count) {
  std::vector<std::string> ids;
  for (size_t i = 0; i < count; ++i) ids.push_back("view_" + std::to_string(1000 + i));
  return ids;
}

avc::mvs_points_t ThroughLcm(const avc::mvs_points_t& message) {
  const std::string bytes = testing::Encode(message);
  avc::mvs_points_t decoded;
  EXPECT_EQ(decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  return decoded;
}

void ExpectEqual(const mvs::MvsPoints& a, const mvs::MvsPoints& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.cloud.positions[i], b.cloud.positions[i]) << "point " << i;
    ASSERT_EQ(a.cloud.normals[i], b.cloud.normals[i]) << "point " << i;
    ASSERT_EQ(a.cloud.colors[i], b.cloud.colors[i]) << "point " << i;
    ASSERT_EQ(a.confidence[i], b.confidence[i]) << "point " << i;
    ASSERT_EQ(a.views[i], b.views[i]) << "point " << i;
  }
}

std::string ErrorOf(const avc::mvs_points_t& message) {
  try {
    MvsPointsFromMessage(message);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(NodeMvsMessage, RoundTripsExactlyThroughLcmBytes) {
  const mvs::MvsPoints points = RandomPoints(500, 300, 7);  // indices above 255 need 2 bytes
  const std::vector<std::string> ids = ImageIds(300);
  const avc::mvs_points_t message = MvsPointsToMessage(points, ids, "scan-mvs-1");
  EXPECT_EQ(message.cloud_id, "scan-mvs-1");
  EXPECT_EQ(message.points.num_points, 500);
  EXPECT_EQ(message.points.point_step, 32);
  EXPECT_EQ(message.points.frame, "world");
  size_t index_count = 0;
  for (const auto& views : points.views) index_count += views.size();
  EXPECT_EQ(message.views.size(), points.size() + 2 * index_count);

  const MvsPointsMessageContent back = MvsPointsFromMessage(ThroughLcm(message));
  EXPECT_EQ(back.image_ids, ids);
  ExpectEqual(back.points, points);
  // Same points, same bytes.
  EXPECT_EQ(testing::Encode(MvsPointsToMessage(points, ids, "scan-mvs-1")),
            testing::Encode(message));
}

TEST(NodeMvsMessage, EmptyCloudRoundTrips) {
  const avc::mvs_points_t message = MvsPointsToMessage({}, {}, "empty");
  const MvsPointsMessageContent back = MvsPointsFromMessage(ThroughLcm(message));
  EXPECT_EQ(back.points.size(), 0u);
  EXPECT_TRUE(back.image_ids.empty());
}

TEST(NodeMvsMessage, PointsAreAPlyWritableCloudWithViewerColourNames) {
  const avc::mvs_points_t message = MvsPointsToMessage(RandomPoints(10, 4, 3), ImageIds(4), "c");
  const std::string ply = products::PointCloudToPly(message.points);
  EXPECT_NE(ply.find("element vertex 10\n"), std::string::npos);
  EXPECT_NE(ply.find("property float nz\nproperty uchar red\nproperty uchar green\n"
                     "property uchar blue\n"),
            std::string::npos)
      << ply.substr(0, 400);
  EXPECT_NE(ply.find("property float confidence\n"), std::string::npos);
}

TEST(NodeMvsMessage, ReadsAnyLayoutByFieldName) {
  const mvs::MvsPoints points = RandomPoints(20, 5, 11);
  avc::mvs_points_t message = MvsPointsToMessage(points, ImageIds(5), "c");
  // Rewrite the records as confidence, r g b, x y z, nx ny nz in 40-byte records.
  avc::point_cloud_t& cloud = message.points;
  const std::vector<uint8_t> old = cloud.data;
  const int32_t new_offset[10] = {8, 12, 16, 20, 24, 28, 4, 5, 6, 0};  // old field order
  const int32_t old_offset[10] = {0, 4, 8, 12, 16, 20, 24, 25, 26, 28};
  cloud.point_step = 40;
  cloud.data.assign(20 * 40, 0xAB);
  cloud.data_size = static_cast<int32_t>(cloud.data.size());
  for (int f = 0; f < 10; ++f) {
    cloud.fields[static_cast<size_t>(f)].offset = new_offset[f];
    const int bytes = f >= 6 && f <= 8 ? 1 : 4;
    for (size_t i = 0; i < 20; ++i) {
      std::copy_n(
          old.begin() + static_cast<long>(i * 32 + static_cast<size_t>(old_offset[f])), bytes,
          cloud.data.begin() + static_cast<long>(i * 40 + static_cast<size_t>(new_offset[f])));
    }
  }
  cloud.fields[6].name = "r";
  cloud.fields[7].name = "g";
  cloud.fields[8].name = "b";
  ExpectEqual(MvsPointsFromMessage(ThroughLcm(message)).points, points);
}

TEST(NodeMvsMessage, RefusesPointsItCannotEncode) {
  mvs::MvsPoints points = RandomPoints(3, 4, 5);
  points.views[0] = {0, 3};
  EXPECT_THROW(MvsPointsToMessage(points, ImageIds(3), "c"), std::invalid_argument);
  points.views[1].assign(256, 0);
  for (uint32_t v = 0; v < 256; ++v) points.views[1][v] = v;
  try {
    MvsPointsToMessage(points, ImageIds(300), "c");
    FAIL() << "encoded 256 views of one point";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("point 1 has 256 views"), std::string::npos)
        << error.what();
  }
  points = RandomPoints(3, 4, 5);
  points.cloud.positions[2].x() = std::nanf("");
  EXPECT_THROW(MvsPointsToMessage(points, ImageIds(4), "c"), std::invalid_argument);
}

TEST(NodeMvsMessage, RefusesMalformedMessagesNamingTheProblem) {
  mvs::MvsPoints points = RandomPoints(6, 4, 9);
  points.views[0] = {0, 3};
  const avc::mvs_points_t good = MvsPointsToMessage(points, ImageIds(4), "cloud7");
  ASSERT_EQ(ErrorOf(good), "");

  avc::mvs_points_t message = good;
  message.points.data.pop_back();
  message.points.data_size -= 1;
  EXPECT_NE(ErrorOf(message).find("do not match"), std::string::npos) << ErrorOf(message);

  message = good;
  message.points.fields.erase(message.points.fields.begin() + 9);
  message.points.num_fields -= 1;
  EXPECT_NE(ErrorOf(message).find("no field 'confidence'"), std::string::npos);

  message = good;
  message.points.fields[3].datatype = avc::point_field_t::TYPE_FLOAT64;
  EXPECT_NE(ErrorOf(message).find("field 'nx'"), std::string::npos);

  message = good;
  message.points.fields[0].offset = 30;
  EXPECT_NE(ErrorOf(message).find("leaves the 32-byte record"), std::string::npos);

  message = good;
  message.views.resize(message.views.size() - 1);
  message.views_size -= 1;
  EXPECT_NE(ErrorOf(message).find("cloud7"), std::string::npos);
  EXPECT_NE(ErrorOf(message).find("view list"), std::string::npos) << ErrorOf(message);

  message = good;
  message.image_ids.pop_back();
  message.num_images -= 1;
  EXPECT_NE(ErrorOf(message).find("refers to image 3 of 3"), std::string::npos) << ErrorOf(message);

  message = good;
  message.views.push_back(0);
  message.views_size += 1;
  EXPECT_NE(ErrorOf(message).find("left over"), std::string::npos);

  message = good;
  for (int b = 0; b < 4; ++b) message.points.data[static_cast<size_t>(28 + b)] = 0x7f;  // conf.
  EXPECT_NE(ErrorOf(message).find("confidence"), std::string::npos) << ErrorOf(message);
}

}  // namespace
}  // namespace avc::messages
