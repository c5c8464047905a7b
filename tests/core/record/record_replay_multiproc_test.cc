// `avc record` as a real process on real udpm:// URLs (inside the test's private network
// namespace), then `avc replay` of what it wrote: the products a producer had acknowledged by
// "recorder" come out of the replay byte for byte, and two replays give identical trees.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <avc/heartbeat_t.hpp>
#include <avc/image_t.hpp>
#include <avc/log_text_t.hpp>
#include <avc/mesh_t.hpp>
#include <avc/point_cloud_t.hpp>
#include <avc/progress_t.hpp>
#include <avc/run_info_t.hpp>
#include <csignal>
#include <map>
#include <optional>
#include <random>
#include <set>

#include "core/bus/bus.h"
#include "core/bus/bus_options.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/launch/child_process.h"
#include "core/products/point_cloud_ply.h"
#include "core/products/product_sender.h"
#include "core/record/log_reader.h"
#include "core/util/sha256.h"
#include "tests/support/test_support.h"

namespace avc::record {
namespace {

using testing::Encode;
using testing::RandomBytes;

namespace fs = std::filesystem;
using std::chrono::milliseconds;
using std::chrono::seconds;

std::string Text(const std::vector<uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

std::string ReadIfExists(const fs::path& path) {
  return fs::exists(path) ? testing::ReadFile(path) : std::string("(no output)");
}

std::vector<std::string> FileList(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path().lexically_relative(dir).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Waits for the child to exit within timeout; "" if it exited 0, else what happened.
std::string ExitProblem(launch::ChildProcess& child, milliseconds timeout) {
  const std::optional<int> status = child.WaitFor(timeout);
  if (!status) return "did not exit within " + std::to_string(timeout.count()) + " ms";
  if (WIFEXITED(*status) && WEXITSTATUS(*status) == 0) return "";
  return launch::DescribeWaitStatus(*status);
}

std::string RunReplay(const fs::path& log, const fs::path& out, const fs::path& output_file) {
  launch::ChildProcess replay = launch::ChildProcess::Spawn(
      {{testing::Executable("avc").string(), "replay", log.string(), "-o", out.string()},
       {},
       "",
       output_file.string()});
  const std::string problem = ExitProblem(replay, seconds(20));
  return problem.empty() ? "" : "avc replay " + problem + ":\n" + ReadIfExists(output_file);
}

TEST(RecordReplay, RecordedProductsReplayByteForByte) {
  testing::TempDir dir("avc-record-mp");
  const fs::path log = dir / "run.lcmlog";
  const fs::path record_output = dir / "record.out";

  // Our side of the bus: the same URLs and cell as the child (flags absent, same environment).
  bus::BusOptions options = bus::ResolveBusOptions({}, "record-test");
  options.max_message_bytes = 64 * 1024;  // several chunks per product
  bus::Bus bus(options);
  bus::EventLoop loop;
  bus.AttachTo(loop);
  std::optional<avc::heartbeat_t> ready;
  bus.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat, [&](const avc::heartbeat_t& beat, const bus::RxInfo&) {
        if (beat.service == "avc-record" && beat.state == avc::heartbeat_t::STATE_READY) {
          ready = beat;
        }
      });

  launch::ChildProcess recorder = launch::ChildProcess::Spawn(
      {{testing::Executable("avc").string(), "record", "-o", log.string(), "--flush-ms", "50"},
       {},
       "",
       record_output.string()});
  ASSERT_TRUE(loop.RunUntil([&] { return ready.has_value() || !recorder.running(); }, seconds(10)));
  ASSERT_TRUE(ready.has_value()) << "avc record never became READY:\n"
                                 << ReadIfExists(record_output);
  EXPECT_EQ(ready->pid, recorder.pid());
  EXPECT_NE(ready->detail.find("events"), std::string::npos) << ready->detail;

  // A few control messages.
  std::vector<std::pair<std::string, std::string>> control;  // (channel, bytes)
  for (int i = 0; i < 3; ++i) {
    avc::log_text_t line{};
    line.level = avc::log_text_t::LEVEL_INFO;
    line.text = "capture " + std::to_string(i);
    bus.Publish(channels::kLog, line);
    control.emplace_back(bus.FullChannel(channels::kLog), Encode(line));
  }
  avc::progress_t progress{};
  progress.task = "scan";
  progress.phase = "INITIAL_CAPTURE";
  progress.done = 3;
  progress.total = 12;
  progress.fraction = 0.25;
  progress.eta_us = -1;
  bus.Publish(channels::kProgress, progress);
  control.emplace_back(bus.FullChannel(channels::kProgress), Encode(progress));

  // Three products that must be acknowledged by "recorder".
  avc::image_t image{};
  image.image_id = "view_0001";
  image.camera_id = "cam0";
  image.width = 640;
  image.height = 480;
  image.pixel_format = avc::image_t::PIXEL_RGB8;
  image.encoding = avc::image_t::ENCODING_PNG;
  image.data = RandomBytes(300'000, 1);
  image.size = static_cast<int32_t>(image.data.size());

  avc::point_cloud_t cloud{};
  cloud.cloud_id = "cloud_0001";
  cloud.frame = "world";
  for (const auto& [name, offset] : {std::pair<const char*, int32_t>{"x", 0}, {"y", 4}, {"z", 8}}) {
    avc::point_field_t field{};
    field.name = name;
    field.offset = offset;
    field.datatype = avc::point_field_t::TYPE_FLOAT32;
    field.count = 1;
    cloud.fields.push_back(field);
  }
  cloud.num_fields = 3;
  cloud.point_step = 12;
  cloud.num_points = 10'000;
  cloud.data = RandomBytes(120'000, 2);
  cloud.data_size = static_cast<int32_t>(cloud.data.size());

  avc::mesh_t mesh{};
  mesh.mesh_id = "mesh_0001";
  mesh.frame = "world";
  mesh.encoding = avc::mesh_t::ENCODING_PLY_BINARY;
  mesh.data = RandomBytes(150'000, 3);
  mesh.data_size = static_cast<int32_t>(mesh.data.size());

  products::SenderOptions sender_options;
  sender_options.required_receivers = {"recorder"};
  products::ProductSender sender(bus, loop, sender_options);
  std::vector<products::SendResult> results;
  auto done = [&](const products::SendResult& r) { results.push_back(r); };
  sender.SendMessage(channels::kProductImage, "images/view_0001", image, done);
  sender.SendMessage(channels::kProductCloud, "clouds/cloud_0001", cloud, done);
  sender.SendMessage(channels::kProductMesh, "meshes/mesh_0001", mesh, done);
  ASSERT_TRUE(loop.RunUntil([&] { return results.size() == 3; }, seconds(20)))
      << results.size() << " of 3 products finished:\n"
      << ReadIfExists(record_output);
  for (const products::SendResult& r : results) EXPECT_TRUE(r.ok) << r.error;

  // Stop: SIGTERM, a clean exit 0 within a bound.
  ASSERT_TRUE(recorder.Signal(SIGTERM));
  const std::string record_problem = ExitProblem(recorder, seconds(10));
  const std::string record_text = ReadIfExists(record_output);
  ASSERT_EQ(record_problem, "") << "avc record:\n" << record_text;
  EXPECT_NE(record_text.find("avc record: wrote"), std::string::npos) << record_text;

  // The log: RUN_INFO first, intact, with every control message as it was sent.
  {
    LogReader reader(log);
    const lcm::LogEvent* first = reader.Next();
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->channel, bus.FullChannel(channels::kRunInfo));
    avc::run_info_t info{};
    ASSERT_GE(info.decode(first->data, 0, first->datalen), 0);
    EXPECT_NE(info.command_line.find("record -o " + log.string()), std::string::npos)
        << info.command_line;
    EXPECT_EQ(info.control_url, bus.options().control_url);
    EXPECT_EQ(info.bulk_url, bus.options().bulk_url);
    std::multiset<std::pair<std::string, std::string>> logged;
    bool recorder_heartbeat = false;
    while (const lcm::LogEvent* event = reader.Next()) {
      const std::string data(static_cast<const char*>(event->data),
                             static_cast<size_t>(event->datalen));
      logged.emplace(event->channel, data);
      if (event->channel == bus.FullChannel(channels::kHeartbeat)) {
        avc::heartbeat_t beat{};
        recorder_heartbeat |=
            beat.decode(event->data, 0, event->datalen) >= 0 && beat.service == "avc-record";
      }
    }
    EXPECT_TRUE(reader.warnings().empty()) << reader.warnings().front();
    EXPECT_FALSE(reader.truncated());
    for (const auto& message : control) {
      EXPECT_EQ(logged.count(message), 1u) << message.first << " not logged exactly once";
    }
    EXPECT_TRUE(recorder_heartbeat) << "the recorder's own heartbeat is part of the cell's traffic";
  }

  // Replay: the archive holds the products exactly as they were sent.
  const fs::path replay1 = dir / "replay1";
  const fs::path replay2 = dir / "replay2";
  ASSERT_EQ(RunReplay(log, replay1, dir / "replay1.out"), "");
  const std::map<std::string, std::string> expected = {
      {"archive/images/view_0001.png", Text(image.data)},
      {"archive/clouds/cloud_0001.ply", products::PointCloudToPly(cloud)},
      {"archive/meshes/mesh_0001.ply", Text(mesh.data)}};
  for (const auto& [file, bytes] : expected) {
    ASSERT_TRUE(fs::exists(replay1 / file)) << file << " missing:\n"
                                            << ReadIfExists(dir / "replay1.out");
    EXPECT_EQ(Sha256Hex(testing::ReadFile(replay1 / file)), Sha256Hex(bytes)) << file;
  }
  EXPECT_TRUE(
      testing::ReadFile(replay1 / "archive/clouds/cloud_0001.ply").ends_with(Text(cloud.data)));
  const std::string manifest = testing::ReadFile(replay1 / "archive/manifest.jsonl");
  EXPECT_EQ(std::count(manifest.begin(), manifest.end(), '\n'), 3) << manifest;
  EXPECT_NE(testing::ReadFile(dir / "replay1.out").find("node archive: 3 products stored"),
            std::string::npos)
      << testing::ReadFile(dir / "replay1.out");

  // Neither command clobbers earlier results: an existing log or a non-empty directory is
  // refused with exit code 1, naming it, and left as it was.
  const std::string log_bytes = testing::ReadFile(log);
  const std::string replay1_manifest = testing::ReadFile(replay1 / "archive/manifest.jsonl");
  for (const std::vector<std::string>& argv :
       {std::vector<std::string>{"record", "-o", log.string()},
        std::vector<std::string>{"replay", log.string(), "-o", replay1.string()}}) {
    std::vector<std::string> full = {testing::Executable("avc").string()};
    full.insert(full.end(), argv.begin(), argv.end());
    const fs::path output = dir / ("refused-" + argv[0] + ".out");
    launch::ChildProcess refused = launch::ChildProcess::Spawn({full, {}, "", output.string()});
    const std::optional<int> status = refused.WaitFor(seconds(10));
    ASSERT_TRUE(status.has_value()) << argv[0] << " did not exit";
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 1)
        << argv[0] << ": " << launch::DescribeWaitStatus(*status);
    const std::string text = testing::ReadFile(output);
    EXPECT_NE(text.find(argv[0] == "record" ? log.string() : replay1.string()), std::string::npos)
        << text;
  }
  EXPECT_EQ(testing::ReadFile(log), log_bytes);
  EXPECT_EQ(testing::ReadFile(replay1 / "archive/manifest.jsonl"), replay1_manifest);

  // A second replay: the same tree, byte for byte.
  ASSERT_EQ(RunReplay(log, replay2, dir / "replay2.out"), "");
  const std::vector<std::string> files = FileList(replay1);
  EXPECT_EQ(files.size(), 4u);
  ASSERT_EQ(files, FileList(replay2));
  for (const std::string& file : files) {
    EXPECT_EQ(testing::ReadFile(replay1 / file), testing::ReadFile(replay2 / file)) << file;
  }
}

}  // namespace
}  // namespace avc::record
