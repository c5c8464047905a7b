#include "core/products/product_archive.h"

#include <gtest/gtest.h>

#include <avc/image_t.hpp>
#include <avc/mesh_t.hpp>

#include "core/bus/channels.h"
#include "core/products/product_sender.h"
#include "core/util/sha256.h"
#include "tests/support/test_support.h"

namespace avc::products {
namespace {

Product FromMessage(const std::string& name, const auto& msg, const std::string& type) {
  Product product;
  product.name = name;
  product.content_type = type;
  product.payload.resize(static_cast<size_t>(msg.getEncodedSize()));
  msg.encode(product.payload.data(), 0, static_cast<int>(product.payload.size()));
  product.sha256 = Sha256Hex(product.payload);
  return product;
}

TEST(ProductArchive, StoredFilesAreWhatPeopleCanOpen) {
  avc::image_t png{};
  png.encoding = avc::image_t::ENCODING_PNG;
  png.data = {0x89, 'P', 'N', 'G'};
  png.size = 4;
  StoredFile file = ToStoredFile(FromMessage("images/view_0001", png, "avc.image_t"));
  EXPECT_EQ(file.relative_path, "images/view_0001.png");
  EXPECT_EQ(file.bytes, std::string("\x89PNG"));

  avc::image_t gray{};
  gray.encoding = avc::image_t::ENCODING_RAW;
  gray.pixel_format = avc::image_t::PIXEL_GRAY8;
  gray.width = 2;
  gray.height = 2;
  gray.row_stride = 3;  // one byte of row padding is dropped
  gray.data = {1, 2, 99, 3, 4, 99};
  gray.size = 6;
  file = ToStoredFile(FromMessage("mask", gray, "avc.image_t"));
  EXPECT_EQ(file.relative_path, "mask.pgm");
  EXPECT_EQ(file.bytes, std::string("P5\n2 2\n255\n\x01\x02\x03\x04"));

  avc::mesh_t mesh{};
  mesh.data = {'p', 'l', 'y'};
  mesh.data_size = 3;
  file = ToStoredFile(FromMessage("mesh", mesh, "avc.mesh_t"));
  EXPECT_EQ(file.relative_path, "mesh.ply");
  EXPECT_EQ(file.bytes, "ply");
}

TEST(ProductArchive, NamesThatLeaveTheArchiveAndUndecodablePayloadsAreRefused) {
  avc::mesh_t mesh{};
  EXPECT_THROW(ToStoredFile(FromMessage("../evil", mesh, "avc.mesh_t")), std::invalid_argument);
  EXPECT_THROW(ToStoredFile(FromMessage("/etc/passwd", mesh, "avc.mesh_t")), std::invalid_argument);
  EXPECT_THROW(ToStoredFile(FromMessage("", mesh, "avc.mesh_t")), std::invalid_argument);
  Product junk;
  junk.name = "x";
  junk.content_type = "avc.mesh_t";
  junk.payload = {1, 2, 3};
  EXPECT_THROW(ToStoredFile(junk), std::invalid_argument);
}

TEST(ProductArchive, ReceivesProductsIntoFilesAndManifest) {
  testing::TempDir dir;
  bus::Bus bus(bus::InProcessBusOptions());
  bus::EventLoop loop;
  bus.AttachTo(loop);
  ProductArchive archive(bus, dir.path() / "archive");
  ProductSender sender(bus, loop);
  avc::mesh_t mesh{};
  mesh.data.assign(100'000, 'm');
  mesh.data_size = 100'000;
  int done = 0;
  sender.SendMessage(channels::kProductMesh, "mesh", mesh, [&](const SendResult& r) {
    EXPECT_TRUE(r.ok);
    ++done;
  });
  sender.SendMessage(channels::kProductMesh, "../escape", mesh, [&](const SendResult&) { ++done; });
  ASSERT_TRUE(loop.RunUntil([&] { return done == 2; }, std::chrono::seconds(10)));
  EXPECT_EQ(testing::ReadFile(dir.path() / "archive" / "mesh.ply"), std::string(100'000, 'm'));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "escape.ply"));
  const std::string manifest = testing::ReadFile(dir.path() / "archive" / "manifest.jsonl");
  EXPECT_NE(manifest.find("\"file\":\"mesh.ply\""), std::string::npos) << manifest;
  EXPECT_EQ(std::count(manifest.begin(), manifest.end(), '\n'), 1);
  EXPECT_EQ(archive.stored(), 1);
}

}  // namespace
}  // namespace avc::products
