#include "core/products/point_cloud_ply.h"

#include <gtest/gtest.h>

#include <cstring>

namespace avc::products {
namespace {

avc::point_field_t Field(const std::string& name, int32_t offset, int8_t type, int32_t count = 1) {
  avc::point_field_t field{};
  field.name = name;
  field.offset = offset;
  field.datatype = type;
  field.count = count;
  return field;
}

avc::point_cloud_t XyzRgbCloud() {
  avc::point_cloud_t cloud{};
  cloud.cloud_id = "c";
  cloud.frame = "world";
  cloud.fields = {Field("x", 0, avc::point_field_t::TYPE_FLOAT32),
                  Field("y", 4, avc::point_field_t::TYPE_FLOAT32),
                  Field("z", 8, avc::point_field_t::TYPE_FLOAT32),
                  Field("rgb", 12, avc::point_field_t::TYPE_UINT8, 3)};
  cloud.num_fields = 4;
  cloud.point_step = 16;  // one byte of padding
  cloud.num_points = 2;
  cloud.data.assign(32, 0);
  const float xyz[3] = {1.5f, -2.f, 3.25f};
  std::memcpy(cloud.data.data(), xyz, sizeof(xyz));
  cloud.data_size = 32;
  return cloud;
}

TEST(PointCloudPly, HeaderDescribesEveryByteOfTheRecord) {
  const std::string ply = PointCloudToPly(XyzRgbCloud());
  const std::string expected_header =
      "ply\nformat binary_little_endian 1.0\ncomment frame world\nelement vertex 2\n"
      "property float x\nproperty float y\nproperty float z\n"
      "property uchar rgb0\nproperty uchar rgb1\nproperty uchar rgb2\n"
      "property uchar pad0\nend_header\n";
  ASSERT_EQ(ply.substr(0, expected_header.size()), expected_header);
  EXPECT_EQ(ply.size(), expected_header.size() + 32);
  float x = 0;
  std::memcpy(&x, ply.data() + expected_header.size(), 4);
  EXPECT_EQ(x, 1.5f);
}

TEST(PointCloudPly, InconsistentCloudsAreRefused) {
  auto cloud = XyzRgbCloud();
  cloud.data_size = 31;
  EXPECT_THROW(PointCloudToPly(cloud), std::invalid_argument);
  cloud = XyzRgbCloud();
  cloud.fields[1].offset = 2;  // overlaps x
  EXPECT_THROW(PointCloudToPly(cloud), std::invalid_argument);
  cloud = XyzRgbCloud();
  cloud.fields[3].count = 5;  // leaves the record
  EXPECT_THROW(PointCloudToPly(cloud), std::invalid_argument);
  cloud = XyzRgbCloud();
  cloud.fields[0].datatype = 42;
  EXPECT_THROW(PointCloudToPly(cloud), std::invalid_argument);
  cloud = XyzRgbCloud();
  cloud.fields[2].count = 754974721;  // count x 4 bytes overflows int (found by fuzzing)
  EXPECT_THROW(PointCloudToPly(cloud), std::invalid_argument);
  // No points but a 2 GB record: a header line per padding byte would never end (fuzzing).
  cloud = XyzRgbCloud();
  cloud.num_points = 0;
  cloud.data_size = 0;
  cloud.data.clear();
  cloud.point_step = 2147483647;
  try {
    PointCloudToPly(cloud);
    ADD_FAILURE() << "a 2 GB record must be refused";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("at most 4096"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace avc::products
