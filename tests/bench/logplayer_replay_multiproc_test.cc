// A scan's recording, played by Debian's lcm-logplayer into freshly started stage services: only
// the jobs the scan sent (PRODUCT/STAGE_JOB, each carrying its input files: the images and
// cameras, the points, the clusters), on a URL no cell uses, with nothing else running. The
// services' answers must be the scan's model, byte for byte: the build's points and the surface's
// mesh. The jobs are all a stage needs, so the log alone reproduces the scan's processing.
// The scan's surfacer runs with a configuration of its own: the scan folder keeps each service's
// configuration (config/<service>.toml, named in scan.json), the fresh services are started with
// those files, and the surface made with the defaults instead differs.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <avc/heartbeat_t.hpp>
#include <avc/stage_result_t.hpp>
#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "bench/chaos/chaos_scan.h"
#include "bench/devices/scan_process.h"
#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/launch/child_process.h"
#include "core/products/chunking.h"
#include "core/products/product_receiver.h"
#include "core/record/log_reader.h"
#include "core/stage/stage_files.h"
#include "core/util/sha256.h"
#include "services/surfacer/surface_step.h"
#include "tests/bench/short_scan.h"
#include "tests/support/test_support.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

// Stage jobs whose every chunk the recording holds, and jobs it holds only part of.
struct RecordedJobs {
  int complete = 0;
  int incomplete = 0;
};

RecordedJobs CountRecordedJobs(const fs::path& log, const std::string& channel) {
  record::LogReader reader(log);
  products::Reassembler reassembler;
  std::set<std::string> seen;
  RecordedJobs jobs;
  while (const lcm::LogEvent* event = reader.Next()) {
    if (event->channel != channel) continue;
    avc::product_chunk_t chunk;
    if (chunk.decode(event->data, 0, event->datalen) < 0) continue;
    seen.insert(chunk.product_id);
    if (reassembler.Add(chunk).status == products::Reassembler::Status::kComplete) ++jobs.complete;
  }
  jobs.incomplete = static_cast<int>(seen.size()) - jobs.complete;
  return jobs;
}

TEST(LogplayerReplay, TheScansJobsPlayedIntoFreshServicesGiveItsModel) {
  testing::TempDir dir("avc-logplayer");
  WriteNominalCalibration(dir / "calibration.yaml", testing::kShortScanWidth,
                          testing::kShortScanHeight);
  bus::BusOptions cell_bus = bus::ResolveBusOptions({}, "logplayer-test");
  cell_bus.cell = "cell-log";
  // The recorder does not acknowledge products, so a chunk its socket dropped is not resent to
  // it: a log that misses part of a job cannot reproduce the scan, whatever the replay does. Such
  // a recording is set aside and the scan run again, at most four times: the property tested is
  // that a complete log reproduces the scan.
  ChaosScanOptions options;
  ChaosScanResult scan;
  RecordedJobs jobs;
  std::vector<fs::path> logs;
  const std::string job_channel = fmt::format("{}/PRODUCT/STAGE_JOB", cell_bus.cell);
  for (int attempt = 0; attempt < 4; ++attempt) {
    options = testing::ShortScan(dir.path(), fmt::format("scan-{}", attempt), cell_bus);
    options.cell.service_args["avc-surfacer"] = {"--set", "surface.final_smoothing.iterations=1"};
    scan = RunChaosScan(options);
    ASSERT_TRUE(scan.error.empty()) << scan.error;
    logs.clear();
    for (const auto& entry : fs::directory_iterator(options.cell.work_dir / "recordings")) {
      logs.push_back(entry.path());
    }
    ASSERT_EQ(logs.size(), 1u);
    jobs = CountRecordedJobs(logs[0], job_channel);
    std::printf("[ measured ] recording %d: %d complete jobs, %d incomplete\n", attempt,
                jobs.complete, jobs.incomplete);
    if (jobs.incomplete == 0) break;
  }
  ASSERT_EQ(jobs.incomplete, 0) << "the recorder missed part of a job in four scans";
  ASSERT_GE(jobs.complete, 3) << "the build, cluster and surface jobs";
  const fs::path scan_dir = options.scan_dir;
  const nlohmann::json stages =
      nlohmann::json::parse(testing::ReadFile(scan_dir / "scan.json")).at("options").at("stages");
  for (const std::string stage : {"plan", "build", "cluster", "surface"}) {
    const nlohmann::json& entry = stages.at(stage);
    const std::string file = entry.at("config_file").get<std::string>();
    EXPECT_EQ(file, fmt::format("config/{}.toml", entry.at("service").get<std::string>()));
    EXPECT_EQ(entry.at("config_sha256").get<std::string>(),
              Sha256Hex(testing::ReadFile(scan_dir / file)))
        << stage;
  }
  EXPECT_NE(testing::ReadFile(scan_dir / "config" / "avc-surfacer.toml")
                .find("[surface.final_smoothing]\niterations = 1\n"),
            std::string::npos);
  // Fresh services on a URL of their own; control and bulk on one group, as the log mixes both.
  const std::string url = "udpm://239.255.76.67:7801?ttl=0&recv_buf_size=4194304";
  const auto args = [&](std::vector<std::string> argv) {
    argv.insert(argv.end(), {"--lcm-url", url, "--bulk-url", url, "--cell", cell_bus.cell});
    return argv;
  };
  const std::string avc = testing::Executable("avc").string();
  std::vector<launch::ChildProcess> services;
  for (const std::string stage : {"builder", "clusterer", "surfacer"}) {
    const fs::path config = scan_dir / "config" / fmt::format("avc-{}.toml", stage);
    services.push_back(launch::ChildProcess::Spawn({args({avc, stage, "--config", config.string()}),
                                                    {},
                                                    "",
                                                    (dir / (stage + ".log")).string()}));
  }
  bus::BusOptions replay_bus = cell_bus;
  replay_bus.control_url = replay_bus.bulk_url = url;
  bus::Bus bus(replay_bus);
  bus::EventLoop loop;
  bus.AttachTo(loop);
  std::set<std::string> ready;
  bus.Subscribe<avc::heartbeat_t>(channels::kHeartbeat,
                                  [&](const avc::heartbeat_t& beat, const bus::RxInfo&) {
                                    if (beat.state == avc::heartbeat_t::STATE_READY) {
                                      ready.insert(beat.service);
                                    }
                                  });
  // The scan's answers went to its own receiver, "avc-scan": this test takes that name.
  std::map<std::string, avc::stage_result_t> results;
  products::ProductReceiver receiver(
      bus, "avc-scan", std::string(channels::kProductStageResult),
      [&](const products::Product& product, const bus::RxInfo&) {
        avc::stage_result_t result;
        if (result.decode(product.payload.data(), 0, static_cast<int>(product.payload.size())) >
            0) {
          results[result.stage] = result;
        }
      });
  ASSERT_TRUE(loop.RunUntil([&] { return ready.size() == 3; }, milliseconds(20000)))
      << ready.size() << " services READY";

  // A log cannot resend what a service's socket dropped, and played at recorded speed the build
  // job's 36 MB come in the bursts the scan's sender paced for a receiver that acknowledges: play
  // the log again, slower each time (at most 3 passes, at 1x, 0.5x and 0.25x). A service answers
  // a job it already has from memory, so a further pass changes nothing else.
  const auto all_answered = [&] {
    return results.count("build") && results.count("cluster") && results.count("surface");
  };
  int passes = 0;
  for (; passes < 3 && !all_answered(); ++passes) {
    launch::ChildProcess player = launch::ChildProcess::Spawn(
        {{"lcm-logplayer", "-s", fmt::format("{}", 1.0 / (1 << passes)), "-e",
          fmt::format("^{}/PRODUCT/STAGE_JOB$", cell_bus.cell), "-l", url, logs[0].string()},
         {},
         "",
         (dir / fmt::format("lcm-logplayer-{}.log", passes)).string()});
    loop.RunUntil([&] { return all_answered() || !player.running(); }, milliseconds(240000));
    // The last job's stage may still be computing when the log ends.
    loop.RunUntil(all_answered, milliseconds(60000));
    player.WaitFor(milliseconds(60000));
  }
  ASSERT_TRUE(all_answered()) << results.size() << " of 3 stages answered after " << passes
                              << " passes\n"
                              << testing::ReadFile(dir / "builder.log")
                              << testing::ReadFile(dir / "clusterer.log")
                              << testing::ReadFile(dir / "surfacer.log");
  std::printf("[ measured ] answered after %d pass(es) of the log\n", passes);
  for (const auto& [stage, result] : results)
    EXPECT_TRUE(result.ok) << stage << ": " << result.error;
  stage::UnpackFiles(results.at("build").files, dir / "replayed");
  stage::UnpackFiles(results.at("surface").files, dir / "replayed");
  const fs::path model = scan_dir / "model";
  EXPECT_EQ(Sha256Hex(testing::ReadFile(dir / "replayed" / "points.ply")),
            Sha256Hex(testing::ReadFile(model / "points.ply")));
  EXPECT_EQ(Sha256Hex(testing::ReadFile(dir / "replayed" / "mesh.ply")), scan.mesh_sha256);
  EXPECT_EQ(Sha256Hex(testing::ReadFile(dir / "replayed" / "traits.csv")),
            Sha256Hex(testing::ReadFile(model / "traits.csv")));
  for (launch::ChildProcess& service : services) service.Signal(SIGTERM);

  // The configuration mattered: the same clusters surfaced with the defaults give another mesh.
  fs::create_directories(dir / "defaults");
  surfacer::SurfaceModel(model, dir / "defaults", surfacer::SurfacerOptions{});
  EXPECT_NE(Sha256Hex(testing::ReadFile(dir / "defaults" / "mesh.ply")), scan.mesh_sha256);
}

}  // namespace
}  // namespace avc::bench
