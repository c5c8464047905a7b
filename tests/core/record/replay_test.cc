// Deterministic replay of a log built here event by event: products arrive in pieces, twice, out
// of order and once corrupted, and every replay must store each intact product exactly once,
// byte for byte the same. Damaged and wrong inputs are reported, naming what is wrong.

#include "core/record/replay.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <avc/heartbeat_t.hpp>
#include <avc/image_t.hpp>
#include <avc/log_text_t.hpp>
#include <avc/mesh_t.hpp>
#include <avc/point_cloud_t.hpp>
#include <avc/product_ack_t.hpp>
#include <avc/product_chunk_t.hpp>
#include <avc/progress_t.hpp>
#include <avc/run_info_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "core/bus/channels.h"
#include "core/products/chunking.h"
#include "core/products/point_cloud_ply.h"
#include "core/products/product.h"
#include "core/products/product_archive.h"
#include "core/record/builtin_nodes.h"
#include "core/record/node_registry.h"
#include "core/util/sha256.h"
#include "tests/support/test_support.h"

namespace avc::record {
namespace {

using testing::Encode;
using testing::RandomBytes;

namespace fs = std::filesystem;

constexpr size_t kChunkCap = 8 * 1024;  // small, so every product is several chunks
constexpr int64_t kStartUtime = 1'700'000'000'000'000;

template <class T>
products::Product MakeProduct(const std::string& id, const std::string& name, const T& msg) {
  products::Product product;
  product.product_id = id;
  product.name = name;
  product.content_type = products::ContentTypeOf<T>();
  const std::string bytes = Encode(msg);
  product.payload.assign(bytes.begin(), bytes.end());
  product.sha256 = Sha256Hex(product.payload);
  product.source = "avc-camera@lab";
  return product;
}

// Writes an LCM log the way the recorder does and remembers where each event starts.
class LogBuilder {
 public:
  explicit LogBuilder(const fs::path& path)
      : file_(std::make_unique<lcm::LogFile>(path.string(), "w")) {
    EXPECT_TRUE(file_->good()) << path;
  }

  void Add(const std::string& channel, const std::string& data) {
    lcm::LogEvent event{};
    event.timestamp = kStartUtime + 1000 * static_cast<int64_t>(offsets_.size());
    event.channel = channel;
    event.datalen = static_cast<int32_t>(data.size());
    event.data = const_cast<char*>(data.data());
    ASSERT_EQ(file_->writeEvent(&event), 0);
    offsets_.push_back(next_offset_);
    lengths_.push_back(data.size());
    channel_lengths_.push_back(channel.size());
    next_offset_ += 4 + 8 + 8 + 4 + 4 + static_cast<int64_t>(channel.size() + data.size());
    bytes_ += static_cast<int64_t>(data.size());
  }
  // One chunk of a product as its producer publishes it (header stamped).
  void AddChunk(const std::string& cell, std::string_view channel, avc::product_chunk_t chunk) {
    chunk.header.utime = kStartUtime + 1000 * static_cast<int64_t>(offsets_.size());
    chunk.header.seq = ++seq_;
    chunk.header.source = "avc-camera@lab";
    chunk.header.cell = cell;
    Add(cell + "/" + std::string(channel), Encode(chunk));
    if (cell == "cell0") ++cell0_chunks_;
  }
  void Close() { file_.reset(); }

  int64_t events() const { return static_cast<int64_t>(offsets_.size()); }
  int64_t bytes() const { return bytes_; }
  // Where the next event will start.
  int64_t next_offset() const { return next_offset_; }
  // Byte offset of the middle of an event's data.
  int64_t middle_of_data(size_t event) const {
    return offsets_.at(event) + 28 + static_cast<int64_t>(channel_lengths_.at(event)) +
           static_cast<int64_t>(lengths_.at(event) / 2);
  }
  int64_t last_utime() const { return kStartUtime + 1000 * (events() - 1); }
  int cell0_chunks() const { return cell0_chunks_; }

 private:
  std::unique_ptr<lcm::LogFile> file_;
  std::vector<int64_t> offsets_;
  std::vector<size_t> lengths_;
  std::vector<size_t> channel_lengths_;
  int64_t next_offset_ = 0;
  int64_t bytes_ = 0;
  int64_t seq_ = 0;
  int cell0_chunks_ = 0;
};

// What a test log holds and what replaying it must produce.
struct TestLog {
  fs::path path;
  int64_t events = 0;
  int64_t bytes = 0;
  int64_t last_utime = 0;
  int cell0_chunks = 0;
  int duplicates = 0;  // chunks of products already complete
  int64_t last_event_middle = 0;
  int64_t last_event_offset = 0;
  // Relative path under archive/ -> exact bytes, for every intact product of cell0.
  std::map<std::string, std::string> expected_files;
  std::map<std::string, std::string> sha_by_name;  // product name -> sha256 of its payload
  std::string last_product_file;                   // stored from the log's last event
};

TestLog BuildTestLog(const fs::path& path) {
  TestLog log;
  log.path = path;
  LogBuilder builder(path);

  avc::run_info_t info{};
  info.header.utime = kStartUtime;
  info.header.seq = 1;
  info.header.source = "avc-record@lab";
  info.header.cell = "cell0";
  info.version = "0.1.0+test";
  info.command_line = "avc record -o scan.lcmlog";
  info.control_url = "udpm://239.255.76.67:7667?ttl=0";
  info.bulk_url = "udpm://239.255.76.67:7668?ttl=0";
  info.hosts = {"lab"};
  info.num_hosts = 1;
  builder.Add("cell0/RUN_INFO", Encode(info));

  avc::heartbeat_t beat{};
  beat.header.cell = "cell0";
  beat.service = "avc-camera";
  beat.state = avc::heartbeat_t::STATE_READY;
  builder.Add("cell0/HEARTBEAT", Encode(beat));

  // 1. A PNG image: in order, one chunk repeated before the product is complete (not a
  // duplicate yet) and two repeated after it (duplicates).
  avc::image_t png{};
  png.image_id = "view_0001";
  png.camera_id = "cam0";
  png.width = 64;
  png.height = 48;
  png.pixel_format = avc::image_t::PIXEL_RGB8;
  png.encoding = avc::image_t::ENCODING_PNG;
  png.data = RandomBytes(30'000, 1);
  const uint8_t signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::copy(std::begin(signature), std::end(signature), png.data.begin());
  png.size = static_cast<int32_t>(png.data.size());
  const auto png_product = MakeProduct("cam@lab/1/1", "images/view_0001", png);
  const auto png_chunks = products::SplitIntoChunks(png_product, kChunkCap);
  EXPECT_GE(png_chunks.size(), 4u);
  for (size_t i = 0; i < png_chunks.size(); ++i) {
    builder.AddChunk("cell0", channels::kProductImage, png_chunks[i]);
    if (i == 2) builder.AddChunk("cell0", channels::kProductImage, png_chunks[1]);
  }
  builder.AddChunk("cell0", channels::kProductImage, png_chunks.front());
  builder.AddChunk("cell0", channels::kProductImage, png_chunks.back());
  log.duplicates += 2;
  log.expected_files["images/view_0001.png"] = std::string(png.data.begin(), png.data.end());

  // 2. A point cloud, chunks in reverse order, interleaved with 3. a raw 8-bit gray image (row
  // padding dropped in the stored PGM).
  avc::point_cloud_t cloud{};
  cloud.cloud_id = "cloud_0001";
  cloud.frame = "world";
  for (const auto& [name, offset, type] :
       {std::tuple<const char*, int32_t, int8_t>{"x", 0, avc::point_field_t::TYPE_FLOAT32},
        {"y", 4, avc::point_field_t::TYPE_FLOAT32},
        {"z", 8, avc::point_field_t::TYPE_FLOAT32},
        {"confidence", 12, avc::point_field_t::TYPE_UINT8}}) {
    avc::point_field_t field{};
    field.name = name;
    field.offset = offset;
    field.datatype = type;
    field.count = 1;
    cloud.fields.push_back(field);
  }
  cloud.num_fields = static_cast<int32_t>(cloud.fields.size());
  cloud.point_step = 16;
  cloud.num_points = 1500;
  cloud.data = RandomBytes(static_cast<size_t>(cloud.num_points * cloud.point_step), 2);
  cloud.data_size = static_cast<int32_t>(cloud.data.size());
  const auto cloud_product = MakeProduct("cam@lab/1/2", "clouds/cloud_0001", cloud);
  auto cloud_chunks = products::SplitIntoChunks(cloud_product, kChunkCap);
  std::reverse(cloud_chunks.begin(), cloud_chunks.end());
  const std::string cloud_ply = products::PointCloudToPly(cloud);
  EXPECT_TRUE(cloud_ply.starts_with("ply\n"));
  EXPECT_TRUE(cloud_ply.ends_with(std::string(cloud.data.begin(), cloud.data.end())));
  log.expected_files["clouds/cloud_0001.ply"] = cloud_ply;

  avc::image_t gray{};
  gray.image_id = "mask_0001";
  gray.width = 100;
  gray.height = 80;
  gray.row_stride = 101;
  gray.pixel_format = avc::image_t::PIXEL_GRAY8;
  gray.encoding = avc::image_t::ENCODING_RAW;
  gray.data = RandomBytes(static_cast<size_t>(gray.row_stride * gray.height), 3);
  gray.size = static_cast<int32_t>(gray.data.size());
  const auto gray_product = MakeProduct("cam@lab/1/3", "images/mask_0001", gray);
  const auto gray_chunks = products::SplitIntoChunks(gray_product, kChunkCap);
  std::string pgm = "P5\n100 80\n255\n";
  for (int y = 0; y < gray.height; ++y) {
    pgm.append(reinterpret_cast<const char*>(gray.data.data()) + y * gray.row_stride, 100);
  }
  log.expected_files["images/mask_0001.pgm"] = pgm;
  for (size_t i = 0; i < std::max(cloud_chunks.size(), gray_chunks.size()); ++i) {
    if (i < cloud_chunks.size())
      builder.AddChunk("cell0", channels::kProductCloud, cloud_chunks[i]);
    if (i < gray_chunks.size()) builder.AddChunk("cell0", channels::kProductImage, gray_chunks[i]);
  }

  // 4. A mesh whose first transmission has a damaged chunk (the sha256 does not match), then the
  // producer's retransmission, shuffled, after the recorder's CORRUPT acknowledgement.
  avc::mesh_t mesh{};
  mesh.mesh_id = "mesh_0001";
  mesh.frame = "world";
  mesh.num_vertices = 100;
  mesh.num_faces = 50;
  mesh.encoding = avc::mesh_t::ENCODING_PLY_BINARY;
  const std::string ply_header = "ply\nformat binary_little_endian 1.0\nelement vertex 100\n";
  mesh.data.assign(ply_header.begin(), ply_header.end());
  const auto mesh_body = RandomBytes(25'000, 4);
  mesh.data.insert(mesh.data.end(), mesh_body.begin(), mesh_body.end());
  mesh.data_size = static_cast<int32_t>(mesh.data.size());
  const auto mesh_product = MakeProduct("cam@lab/1/4", "meshes/mesh_0001", mesh);
  auto mesh_chunks = products::SplitIntoChunks(mesh_product, kChunkCap);
  for (size_t i = 0; i < mesh_chunks.size(); ++i) {
    avc::product_chunk_t chunk = mesh_chunks[i];
    if (i == 1) chunk.data[10] ^= 0x40;
    builder.AddChunk("cell0", channels::kProductMesh, chunk);
  }
  avc::product_ack_t corrupt{};
  corrupt.header.cell = "cell0";
  corrupt.product_id = mesh_product.product_id;
  corrupt.receiver = "recorder";
  corrupt.status = avc::product_ack_t::STATUS_CORRUPT;
  builder.Add("cell0/PRODUCT_ACK", Encode(corrupt));
  std::mt19937 shuffle_rng(5);
  std::shuffle(mesh_chunks.begin(), mesh_chunks.end(), shuffle_rng);
  for (avc::product_chunk_t chunk : mesh_chunks) {
    chunk.attempt = 1;
    builder.AddChunk("cell0", channels::kProductMesh, chunk);
  }
  log.expected_files["meshes/mesh_0001.ply"] = std::string(mesh.data.begin(), mesh.data.end());

  // Traffic of another cell, including a product: not ours to store.
  avc::image_t other{};
  other.encoding = avc::image_t::ENCODING_PNG;
  other.data = RandomBytes(2'000, 6);
  other.size = static_cast<int32_t>(other.data.size());
  for (const auto& chunk :
       products::SplitIntoChunks(MakeProduct("cam@lab9/1/1", "images/other", other), kChunkCap)) {
    builder.AddChunk("cell9", channels::kProductImage, chunk);
  }
  avc::log_text_t line{};
  line.text = "scan finished";
  builder.Add("cell0/LOG", Encode(line));

  // 5. Last event: a product of a type without a file format, stored as its LCM encoding.
  avc::progress_t progress{};
  progress.task = "scan";
  progress.phase = "DONE";
  progress.done = 12;
  progress.total = 12;
  progress.fraction = 1.0;
  progress.eta_us = -1;
  const auto progress_product = MakeProduct("cam@lab/1/5", "reports/progress", progress);
  const auto progress_chunks = products::SplitIntoChunks(progress_product, kChunkCap);
  EXPECT_EQ(progress_chunks.size(), 1u);
  log.last_event_offset = builder.next_offset();
  builder.AddChunk("cell0", channels::kProductPreview, progress_chunks[0]);
  log.last_event_middle = builder.middle_of_data(static_cast<size_t>(builder.events() - 1));
  log.expected_files["reports/progress.lcm"] = Encode(progress);
  log.last_product_file = "reports/progress.lcm";

  for (const auto* product :
       {&png_product, &cloud_product, &gray_product, &mesh_product, &progress_product}) {
    log.sha_by_name[product->name] = product->sha256;
  }
  log.events = builder.events();
  log.bytes = builder.bytes();
  log.last_utime = builder.last_utime();
  log.cell0_chunks = builder.cell0_chunks();
  builder.Close();
  return log;
}

// Every regular file under dir, relative to it, sorted.
std::vector<std::string> FileList(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    EXPECT_TRUE(entry.is_regular_file() || entry.is_directory()) << entry.path();
    if (entry.is_regular_file()) files.push_back(entry.path().lexically_relative(dir).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<nlohmann::json> ManifestLines(const fs::path& archive) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(testing::ReadFile(archive / "manifest.jsonl"));
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

class ReplayTest : public ::testing::Test {
 protected:
  void SetUp() override {
    RegisterBuiltinNodes(registry_);
    log_ = BuildTestLog(dir_ / "scan.lcmlog");
  }

  ReplaySummary Replay(const fs::path& output, const fs::path& log_path = {},
                       std::vector<std::string> nodes = {}, std::string cell = {}) {
    ReplayOptions options;
    options.log = log_path.empty() ? log_.path : log_path;
    options.output_dir = output;
    options.nodes = std::move(nodes);
    options.cell = std::move(cell);
    return ReplayRunner(registry_, options).Run();
  }

  // Expects ReplayError whose message contains every one of parts.
  void ExpectReplayError(const ReplayOptions& options, const std::vector<std::string>& parts) {
    try {
      ReplayRunner(registry_, options).Run();
      ADD_FAILURE() << "no ReplayError for " << options.log;
    } catch (const ReplayError& e) {
      for (const std::string& part : parts) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
            << "'" << e.what() << "' does not mention '" << part << "'";
      }
    }
  }

  testing::TempDir dir_{"avc-replay"};
  NodeRegistry registry_;
  TestLog log_;
};

TEST_F(ReplayTest, TwoReplaysStoreEveryIntactProductOnceAndIdentically) {
  const ReplaySummary first = Replay(dir_ / "replay1");
  const ReplaySummary second = Replay(dir_ / "replay2", {}, {"archive"});

  // The two trees: same sorted file list, same bytes in every file.
  const std::vector<std::string> files = FileList(dir_ / "replay1");
  EXPECT_EQ(files, FileList(dir_ / "replay2"));
  const std::vector<std::string> expected_list = {
      "archive/clouds/cloud_0001.ply", "archive/images/mask_0001.pgm",
      "archive/images/view_0001.png",  "archive/manifest.jsonl",
      "archive/meshes/mesh_0001.ply",  "archive/reports/progress.lcm"};
  EXPECT_EQ(files, expected_list);
  for (const std::string& file : files) {
    EXPECT_EQ(testing::ReadFile(dir_ / "replay1" / file),
              testing::ReadFile(dir_ / "replay2" / file))
        << file << " differs between the two replays";
  }

  // Every intact product exactly once, with exactly the bytes sent; nothing of cell9.
  for (const auto& [file, bytes] : log_.expected_files) {
    EXPECT_EQ(testing::ReadFile(dir_ / "replay1" / "archive" / file), bytes) << file;
  }
  const std::vector<nlohmann::json> manifest = ManifestLines(dir_ / "replay1" / "archive");
  ASSERT_EQ(manifest.size(), log_.expected_files.size());
  std::map<std::string, int> times_stored;
  for (const nlohmann::json& line : manifest) {
    const std::string name = line.at("name").get<std::string>();
    ++times_stored[name];
    ASSERT_TRUE(log_.sha_by_name.contains(name)) << name;
    EXPECT_EQ(line.at("sha256").get<std::string>(), log_.sha_by_name.at(name)) << name;
    EXPECT_EQ(line.at("source").get<std::string>(), "avc-camera@lab");
    EXPECT_TRUE(log_.expected_files.contains(line.at("file").get<std::string>())) << line.dump();
  }
  for (const auto& [name, sha] : log_.sha_by_name) EXPECT_EQ(times_stored[name], 1) << name;

  // The summaries: every event, nothing to warn about, the same account twice.
  for (const ReplaySummary* summary : {&first, &second}) {
    EXPECT_EQ(summary->cell, "cell0");
    EXPECT_EQ(summary->events, log_.events);
    EXPECT_EQ(summary->bytes, log_.bytes);
    EXPECT_EQ(summary->first_utime, kStartUtime);
    EXPECT_EQ(summary->last_utime, log_.last_utime);
    EXPECT_TRUE(summary->warnings.empty()) << summary->warnings.front();
    ASSERT_EQ(summary->nodes.size(), 1u);
    const NodeOutput& node = summary->nodes[0];
    EXPECT_EQ(node.name, "archive");
    EXPECT_EQ(node.description,
              fmt::format("{} products stored ({} chunks, {} duplicate, 1 corrupt, 0 invalid)",
                          log_.expected_files.size(), log_.cell0_chunks, log_.duplicates));
    std::vector<std::string> node_files;
    for (const fs::path& file : node.files) node_files.push_back(file.string());
    EXPECT_EQ(node_files, expected_list);
  }
  EXPECT_EQ(second.nodes[0].dir, dir_ / "replay2" / "archive");
}

TEST_F(ReplayTest, OtherCellIsReplayedWhenAsked) {
  const ReplaySummary summary = Replay(dir_ / "cell9", {}, {}, "cell9");
  EXPECT_EQ(summary.cell, "cell9");
  EXPECT_EQ(summary.events, log_.events);
  EXPECT_EQ(FileList(dir_ / "cell9"),
            (std::vector<std::string>{"archive/images/other.png", "archive/manifest.jsonl"}));
}

TEST_F(ReplayTest, TruncatedLogReplaysUpToTheDamageWithAWarning) {
  const std::string full = testing::ReadFile(log_.path);
  ASSERT_LT(log_.last_event_middle, static_cast<int64_t>(full.size()));
  // A crash in the middle of the last event's data, and one right after its first two bytes.
  const std::vector<std::pair<std::string, int64_t>> cuts = {
      {"mid-data.lcmlog", log_.last_event_middle},
      {"two-bytes.lcmlog", log_.last_event_offset + 2}};
  for (const auto& [name, size] : cuts) {
    SCOPED_TRACE(name);
    const fs::path cut = dir_ / name;
    testing::WriteFile(cut, full.substr(0, static_cast<size_t>(size)));
    ReplaySummary summary;
    ASSERT_NO_THROW(summary = Replay(dir_ / ("out-" + name), cut));
    EXPECT_EQ(summary.events, log_.events - 1);
    ASSERT_EQ(summary.warnings.size(), 1u);
    const std::string& warning = summary.warnings[0];
    EXPECT_NE(warning.find(cut.string()), std::string::npos) << warning;
    EXPECT_NE(warning.find("truncated"), std::string::npos) << warning;
    // Events are numbered from 0, as LCM numbers them: the damaged one is the last.
    EXPECT_NE(
        warning.find(fmt::format("event {} at byte {}", log_.events - 1, log_.last_event_offset)),
        std::string::npos)
        << warning;
    // Everything before the damage is stored, as in a full replay; the cut product is not.
    const fs::path archive = dir_ / ("out-" + name) / "archive";
    for (const auto& [file, bytes] : log_.expected_files) {
      if (file == log_.last_product_file) {
        EXPECT_FALSE(fs::exists(archive / file)) << file;
      } else {
        EXPECT_EQ(testing::ReadFile(archive / file), bytes) << file;
      }
    }
    EXPECT_EQ(ManifestLines(archive).size(), log_.expected_files.size() - 1);
  }
}

TEST_F(ReplayTest, AFileThatIsNotAnLcmLogIsAnErrorNamingIt) {
  const fs::path text = dir_ / "notes.txt";
  std::string contents;
  for (int i = 0; i < 200; ++i)
    contents += "this is not an LCM log, line " + std::to_string(i) + "\n";
  testing::WriteFile(text, contents);
  const fs::path empty = dir_ / "empty.lcmlog";
  testing::WriteFile(empty, "");
  const fs::path missing = dir_ / "missing.lcmlog";
  int run = 0;
  for (const fs::path& log : {text, empty, missing}) {
    for (const std::string cell : {"", "cell0"}) {
      SCOPED_TRACE(log.string() + " cell '" + cell + "'");
      ReplayOptions options;
      options.log = log;
      options.output_dir = dir_ / ("out" + std::to_string(++run));
      options.cell = cell;
      ExpectReplayError(options, {log.string()});
      EXPECT_FALSE(fs::exists(options.output_dir))
          << "nothing is created for a log that cannot be replayed";
    }
  }
}

// A RUN_INFO whose header.source claims a length of 0: lcm-gen's decode throws std::length_error
// on it instead of failing (found by fuzz/lcm_log_fuzzer). The event is taken as undecodable and
// the cell comes from its channel, as for any other malformed RUN_INFO.
TEST_F(ReplayTest, RunInfoWithAZeroStringLengthIsUndecodableNotAnException) {
  const fs::path path = dir_ / "bad-run-info.lcmlog";
  {
    LogBuilder log(path);
    // Fingerprint, utime, seq, then source's length 0.
    log.Add("cell7/RUN_INFO", Encode(avc::run_info_t{}).substr(0, 8) + std::string(24, '\0'));
  }
  std::string cell;
  EXPECT_NO_THROW(cell = CellOfLog(path));
  EXPECT_EQ(cell, "cell7");
}

TEST_F(ReplayTest, UnknownNodeIsAnErrorListingTheKnownOnes) {
  ReplayOptions options;
  options.log = log_.path;
  options.output_dir = dir_ / "out";
  options.nodes = {"archive", "reconstruct"};
  ExpectReplayError(options, {"reconstruct", "known: archive"});
  EXPECT_FALSE(fs::exists(dir_ / "out"));

  options.nodes = {"archive", "archive"};
  ExpectReplayError(options, {"archive", "twice"});
}

TEST_F(ReplayTest, NonEmptyOutputDirectoryIsRefused) {
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  testing::WriteFile(out / "earlier.txt", "an earlier replay");
  ReplayOptions options;
  options.log = log_.path;
  options.output_dir = out;
  ExpectReplayError(options, {out.string(), "not empty"});
  EXPECT_EQ(FileList(out), std::vector<std::string>{"earlier.txt"});
  EXPECT_EQ(testing::ReadFile(out / "earlier.txt"), "an earlier replay");

  // An existing empty directory is fine.
  const fs::path empty = dir_ / "empty";
  fs::create_directories(empty);
  EXPECT_EQ(Replay(empty).events, log_.events);
}

}  // namespace
}  // namespace avc::record
