// A reconstruction stage over an in-process bus: the job's files out, the stage's files back,
// its progress heard on the way; failures, a silent service, a repeated request id and an
// answer for another scan each handled as the client promises (core/stage/stage_client.h).

#include <gtest/gtest.h>

#include <atomic>
#include <avc/stage_job_t.hpp>
#include <avc/stage_result_t.hpp>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "core/bus/channels.h"
#include "core/bus/decode.h"
#include "core/bus/heartbeat.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"
#include "core/stage/stage_client.h"
#include "core/stage/stage_files.h"
#include "core/stage/stage_server.h"
#include "core/util/file_io.h"
#include "core/util/sha256.h"
#include "tests/support/test_support.h"

namespace avc::stage {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

constexpr char kService[] = "avc-test-stage";

struct Harness {
  Harness() : bus(bus::InProcessBusOptions("cell0", "stage-test")) { bus.AttachTo(loop); }
  bus::Bus bus;
  bus::EventLoop loop;
};

avc::file_t File(const std::string& path, const std::string& text) {
  avc::file_t file;
  file.path = path;
  file.data.assign(text.begin(), text.end());
  file.size = static_cast<int32_t>(file.data.size());
  return file;
}

std::string Text(const avc::file_t& file) {
  return std::string(file.data.begin(), file.data.end());
}

StageRequest Request(std::vector<avc::file_t> files) {
  StageRequest request;
  request.service = kService;
  request.stage = "upper";
  request.scan_id = "scan-1";
  request.files = std::move(files);
  request.timeout = std::chrono::seconds(20);
  request.silence_timeout = std::chrono::seconds(3);
  return request;
}

// Upper-cases every input file into out/, and says so on its progress line.
StageHandler UpperCase(std::atomic<int>* runs) {
  return [runs](const StageWork& work) {
    ++*runs;
    for (const avc::file_t& file : PackFolder(work.input_dir)) {
      std::string text = Text(file);
      for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      fs::create_directories((work.output_dir / file.path).parent_path());
      WriteFileAtomically(work.output_dir / file.path, text);
    }
    work.progress("upper-cased");
  };
}

TEST(StageFiles, PackedFolderIsSortedAndUnpacksToTheSameFiles) {
  testing::TempDir dir("avc-stage-files");
  UnpackFiles({File("b.txt", "two"), File("a/x.bin", std::string("\0\1\2", 3))}, dir.path() / "in");
  const std::vector<avc::file_t> files = PackFolder(dir.path() / "in");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].path, "a/x.bin");
  EXPECT_EQ(files[0].size, 3);
  EXPECT_EQ(files[1].path, "b.txt");
  EXPECT_EQ(Text(files[1]), "two");
  EXPECT_EQ(FileBytes(files), 6);
}

TEST(StageFiles, PathsLeavingTheFolderOrWrongSizesAreRefusedByName) {
  testing::TempDir dir("avc-stage-files-bad");
  for (const char* path : {"../escape", "/etc/passwd", "a/../../b", "", "folder/"}) {
    try {
      UnpackFiles({File(path, "x")}, dir.path());
      ADD_FAILURE() << "accepted '" << path << "'";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find(std::string("'") + path + "'"), std::string::npos)
          << error.what();
    }
  }
  avc::file_t lying = File("ok.txt", "abc");
  lying.size = 7;
  EXPECT_THROW(UnpackFiles({lying}, dir.path()), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir.path().parent_path() / "escape"));
}

TEST(Stage, JobFilesGoOutAndTheStagesFilesComeBackWithItsProgress) {
  Harness h;
  bus::HeartbeatPublisher beat(h.bus, h.loop, kService, milliseconds(100));
  std::atomic<int> runs{0};
  StageServer server(h.bus, h.loop, kService, "upper", UpperCase(&runs));
  StageClient client(h.bus, h.loop, "stage-client");
  std::vector<std::string> heard;
  const StageAnswer answer =
      client.Run(Request({File("images/a.txt", "leaf"), File("b.txt", "stem")}),
                 [&](const std::string& line) { heard.push_back(line); });
  ASSERT_EQ(answer.files.size(), 2u);
  EXPECT_EQ(answer.files[0].path, "b.txt");
  EXPECT_EQ(Text(answer.files[0]), "STEM");
  EXPECT_EQ(answer.files[1].path, "images/a.txt");
  EXPECT_EQ(Text(answer.files[1]), "LEAF");
  EXPECT_EQ(answer.bytes_sent, 8);
  EXPECT_EQ(answer.bytes_received, 8);
  EXPECT_EQ(answer.sends, 1);
  EXPECT_EQ(runs.load(), 1);
  EXPECT_EQ(heard, std::vector<std::string>{"upper-cased"});
  // A second job is a new request: it runs again.
  client.Run(Request({File("c.txt", "root")}));
  EXPECT_EQ(runs.load(), 2);
}

TEST(Stage, AFailingStageIsAStageFailureNamingTheServiceAndItsReason) {
  Harness h;
  bus::HeartbeatPublisher beat(h.bus, h.loop, kService, milliseconds(100));
  StageServer server(h.bus, h.loop, kService, "upper",
                     [](const StageWork&) { throw std::runtime_error("no plant in view_0003"); });
  StageClient client(h.bus, h.loop, "stage-client");
  try {
    client.Run(Request({File("a.txt", "x")}));
    FAIL() << "no failure";
  } catch (const StageFailure& failure) {
    const std::string what = failure.what();
    EXPECT_NE(what.find(kService), std::string::npos) << what;
    EXPECT_NE(what.find("no plant in view_0003"), std::string::npos) << what;
  }
}

TEST(Stage, AServiceThatIsNotRunningIsNamedAfterTheSilenceTimeout) {
  Harness h;
  StageClient client(h.bus, h.loop, "stage-client");
  StageRequest request = Request({File("a.txt", "x")});
  request.silence_timeout = std::chrono::seconds(1);
  const auto start = std::chrono::steady_clock::now();
  try {
    client.Run(request);
    FAIL() << "no failure";
  } catch (const StageFailure& failure) {
    const std::string what = failure.what();
    EXPECT_NE(what.find(kService), std::string::npos) << what;
    EXPECT_NE(what.find("no heartbeat"), std::string::npos) << what;
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

// A job sent twice under one request id (a lost result, a restarted requester) runs once and is
// answered twice.
TEST(Stage, ARepeatedRequestIdIsAnsweredFromMemoryWithoutRunningAgain) {
  Harness h;
  std::atomic<int> runs{0};
  StageServer server(h.bus, h.loop, kService, "upper", UpperCase(&runs));
  int answers = 0;
  products::ProductReceiver results(
      h.bus, "raw-client", std::string(channels::kProductStageResult),
      [&](const products::Product& product, const bus::RxInfo&) {
        avc::stage_result_t result{};
        ASSERT_TRUE(bus::DecodeMessage(product.payload.data(), product.payload.size(), &result));
        EXPECT_TRUE(result.ok) << result.error;
        EXPECT_EQ(result.request_id, "job-7");
        ++answers;
      });
  products::SenderOptions options;
  options.required_receivers = {kService};
  products::ProductSender sender(h.bus, h.loop, options);
  avc::stage_job_t job{};
  job.request_id = "job-7";
  job.scan_id = "scan-1";
  job.stage = "upper";
  job.service = kService;
  job.reply_to = "raw-client";
  job.files = {File("a.txt", "x")};
  job.num_files = 1;
  sender.SendMessage(channels::kProductStageJob, "stage/job-7", job);
  ASSERT_TRUE(h.loop.RunUntil([&] { return answers == 1; }, std::chrono::seconds(10)));
  sender.SendMessage(channels::kProductStageJob, "stage/job-7-again", job);
  ASSERT_TRUE(h.loop.RunUntil([&] { return answers == 2; }, std::chrono::seconds(10)));
  EXPECT_EQ(runs.load(), 1);
  EXPECT_EQ(server.stats().answered_again, 1);
}

// The service takes the job and dies (a crash); another process of it comes up: the client
// hears the new pid and sends the job again, which the new process runs.
TEST(Stage, AJobLostInACrashIsSentAgainToTheRestartedService) {
  Harness h;
  const auto beat_as = [&](int32_t pid) {
    avc::heartbeat_t beat{};
    beat.service = kService;
    beat.pid = pid;
    beat.state = avc::heartbeat_t::STATE_READY;
    h.bus.Publish(channels::kHeartbeat, beat);
  };
  int32_t pid = 111;
  const bus::EventLoop::TimerId beats = h.loop.AddTimer(
      milliseconds(100), [&] { beat_as(pid); }, /*repeating=*/true);
  std::atomic<int> runs{0};
  std::unique_ptr<StageServer> restarted;
  // The first process: acknowledges the job, then is gone.
  std::unique_ptr<products::ProductReceiver> crashing;
  crashing = std::make_unique<products::ProductReceiver>(
      h.bus, kService, std::string(channels::kProductStageJob),
      [&](const products::Product&, const bus::RxInfo&) {
        h.loop.Post([&] {
          crashing.reset();
          pid = 222;
          restarted =
              std::make_unique<StageServer>(h.bus, h.loop, kService, "upper", UpperCase(&runs));
        });
      });
  h.loop.RunUntil([] { return false; }, milliseconds(250));  // pid 111 heard first
  StageClient client(h.bus, h.loop, "stage-client");
  h.loop.RunUntil([] { return false; }, milliseconds(250));
  const StageAnswer answer = client.Run(Request({File("a.txt", "seed")}));
  EXPECT_EQ(answer.sends, 2);
  EXPECT_EQ(runs.load(), 1);
  ASSERT_EQ(answer.files.size(), 1u);
  EXPECT_EQ(Text(answer.files[0]), "SEED");
  h.loop.CancelTimer(beats);
}

// A service that answers the request with another scan's result: the client keeps nothing.
// An impostor service answers every job with a result `spoil` makes wrong; the client must
// refuse it with a failure naming the service and `expected`.
void ExpectResultRefused(const std::function<void(avc::stage_result_t*)>& spoil,
                         const std::string& expected) {
  Harness h;
  bus::HeartbeatPublisher beat(h.bus, h.loop, kService, milliseconds(100));
  products::SenderOptions options;
  options.required_receivers = {"stage-client"};
  products::ProductSender sender(h.bus, h.loop, options);
  products::ProductReceiver impostor(
      h.bus, kService, std::string(channels::kProductStageJob),
      [&](const products::Product& product, const bus::RxInfo&) {
        avc::stage_job_t job{};
        ASSERT_TRUE(bus::DecodeMessage(product.payload.data(), product.payload.size(), &job));
        avc::stage_result_t result{};
        result.request_id = job.request_id;
        result.scan_id = job.scan_id;
        result.stage = job.stage;
        result.service = job.service;
        result.ok = true;
        result.files = {File("mesh.ply", "not yours")};
        result.num_files = 1;
        spoil(&result);
        sender.SendMessage(channels::kProductStageResult, "stage/x", result);
      });
  StageClient client(h.bus, h.loop, "stage-client");
  try {
    client.Run(Request({File("a.txt", "x")}));
    FAIL() << "accepted a result that should be refused: " << expected;
  } catch (const StageFailure& failure) {
    const std::string what = failure.what();
    EXPECT_NE(what.find(expected), std::string::npos) << what;
    EXPECT_NE(what.find(kService), std::string::npos) << what;
  }
}

TEST(Stage, AnAnswerForAnotherScanIsRefused) {
  ExpectResultRefused([](avc::stage_result_t* result) { result->scan_id = "another-scan"; },
                      "another-scan");
}

TEST(Stage, AnAnswerWhoseConfigurationDoesNotMatchItsNameIsRefused) {
  ExpectResultRefused(
      [](avc::stage_result_t* result) {
        result->config_text = "window = 7\n";
        result->config_sha256 = Sha256Hex("window = 5\n");
      },
      "configuration text does not match its SHA-256");
}

// The service's configuration in force comes back with every answer, named by its SHA-256.
TEST(Stage, TheAnswerNamesAndCarriesTheServicesConfiguration) {
  Harness h;
  bus::HeartbeatPublisher beat(h.bus, h.loop, kService, milliseconds(100));
  std::atomic<int> runs{0};
  StageServerOptions options;
  options.service = kService;
  options.stage = "upper";
  options.handler = UpperCase(&runs);
  options.config_text = "[upper]\nalphabet = \"latin\"\n";
  options.config_sha256 = Sha256Hex(options.config_text);
  StageServer server(h.bus, h.loop, options);
  StageClient client(h.bus, h.loop, "stage-client");
  const StageAnswer answer = client.Run(Request({File("a.txt", "leaf")}));
  EXPECT_EQ(answer.config_text, options.config_text);
  EXPECT_EQ(answer.config_sha256, options.config_sha256);
}

TEST(Stage, AJobForAnotherStageIsRefusedWithTheReason) {
  Harness h;
  bus::HeartbeatPublisher beat(h.bus, h.loop, kService, milliseconds(100));
  std::atomic<int> runs{0};
  StageServer server(h.bus, h.loop, kService, "upper", UpperCase(&runs));
  StageClient client(h.bus, h.loop, "stage-client");
  StageRequest request = Request({File("a.txt", "x")});
  request.stage = "lower";
  try {
    client.Run(request);
    FAIL() << "no failure";
  } catch (const StageFailure& failure) {
    EXPECT_NE(std::string(failure.what()).find("runs stage 'upper', not 'lower'"),
              std::string::npos)
        << failure.what();
  }
  EXPECT_EQ(runs.load(), 0);
}

}  // namespace
}  // namespace avc::stage
