// The scan across two machines, as a lab runs it: the cell (simulator, drivers, recorder) and
// `avc scan` in one network namespace, avc-planner, -builder, -clusterer and -surfacer in
// another, joined only by a veth pair that carries the bus's multicast at ttl=1. The scan must
// end with the same images, cameras and mesh, byte for byte, as the same scan on one host, and
// the bus traffic must have crossed the link. Needs root (CAP_NET_ADMIN) for the namespaces;
// skipped, saying so, without it.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/chaos/chaos_compare.h"
#include "bench/chaos/chaos_scan.h"
#include "bench/devices/scan_process.h"
#include "core/launch/child_process.h"
#include "tests/bench/short_scan.h"
#include "tests/support/test_support.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

// Runs a command to its end; its exit code (-1 when it did not exit), its output in `output`.
int Run(const std::vector<std::string>& argv, const fs::path& log, std::string* output = nullptr) {
  launch::ChildProcess child = launch::ChildProcess::Spawn({argv, {}, "", log.string()});
  const std::optional<int> status = child.WaitFor(std::chrono::milliseconds(20000));
  if (output) *output = testing::ReadFile(log);
  return status && WIFEXITED(*status) ? WEXITSTATUS(*status) : -1;
}

// Two network namespaces joined by a veth pair, each with multicast routed onto the link.
class TwoHosts {
 public:
  explicit TwoHosts(fs::path log) : log_(std::move(log)) {
    const int id = static_cast<int>(getpid() % 100000);
    cell_ = fmt::format("avc-cell-{}", id);
    services_ = fmt::format("avc-svc-{}", id);
    cell_link_ = fmt::format("avcc{}", id);
    services_link_ = fmt::format("avcs{}", id);
  }
  ~TwoHosts() {
    for (const std::string& ns : created_) Run({"ip", "netns", "del", ns}, log_);
  }

  // Empty when the namespaces are up, else why not.
  std::string Create() {
    for (const std::string& ns : {cell_, services_}) {
      if (Run({"ip", "netns", "add", ns}, log_) != 0) return Failed("ip netns add " + ns);
      created_.push_back(ns);
    }
    const std::vector<std::vector<std::string>> steps = {
        {"ip", "link", "add", cell_link_, "netns", cell_, "type", "veth", "peer", "name",
         services_link_, "netns", services_},
        {"ip", "-n", cell_, "addr", "add", "10.213.7.1/24", "dev", cell_link_},
        {"ip", "-n", services_, "addr", "add", "10.213.7.2/24", "dev", services_link_},
        {"ip", "-n", cell_, "link", "set", "lo", "up"},
        {"ip", "-n", services_, "link", "set", "lo", "up"},
        {"ip", "-n", cell_, "link", "set", cell_link_, "up"},
        {"ip", "-n", services_, "link", "set", services_link_, "up"},
        {"ip", "-n", cell_, "route", "add", "224.0.0.0/4", "dev", cell_link_},
        {"ip", "-n", services_, "route", "add", "224.0.0.0/4", "dev", services_link_}};
    for (const auto& step : steps) {
      if (Run(step, log_) != 0) return Failed(fmt::format("{}", fmt::join(step, " ")));
    }
    return "";
  }

  std::vector<std::string> CellPrefix() const { return {"ip", "netns", "exec", cell_}; }
  std::vector<std::string> ServicePrefix() const { return {"ip", "netns", "exec", services_}; }

  // Bytes the cell's end of the link sent and received.
  std::pair<int64_t, int64_t> CellLinkBytes() const {
    const fs::path stats_log = log_.parent_path() / "link-stats.json";
    fs::remove(stats_log);  // the log is appended to
    std::string text;
    Run({"ip", "-n", cell_, "-j", "-s", "link", "show", cell_link_}, stats_log, &text);
    const nlohmann::json links = nlohmann::json::parse(text.substr(text.find('[')));
    const nlohmann::json& stats = links.at(0).at("stats64");
    return {stats.at("tx").at("bytes").get<int64_t>(), stats.at("rx").at("bytes").get<int64_t>()};
  }

 private:
  std::string Failed(const std::string& what) const {
    return fmt::format("{} failed: {}", what, testing::ReadFile(log_));
  }

  fs::path log_;
  std::string cell_, services_, cell_link_, services_link_;
  std::vector<std::string> created_;
};

// The short scan on its own URLs: ttl=1 lets the bus cross the link, ttl=0 keeps it on the host.
ChaosScanOptions Scan(const testing::TempDir& dir, const std::string& name, int port, int ttl) {
  bus::BusOptions bus;
  bus.control_url = fmt::format("udpm://239.255.76.67:{}?ttl={}", port, ttl);
  bus.bulk_url = fmt::format("udpm://239.255.76.67:{}?ttl={}&recv_buf_size=4194304", port + 1, ttl);
  bus.cell = "cell-two";
  return testing::ShortScan(dir.path(), name, bus);
}

TEST(TwoHostsMultiproc, TheScanWithItsServicesOnAnotherHostEndsAsOnOneHost) {
  testing::TempDir dir("avc-two-hosts");
  TwoHosts hosts(dir / "ip.log");
  if (const std::string problem = hosts.Create(); !problem.empty()) {
    GTEST_SKIP() << "cannot make network namespaces here (needs root): " << problem;
  }
  WriteNominalCalibration(dir / "calibration.yaml", testing::kShortScanWidth,
                          testing::kShortScanHeight);

  const ChaosScanResult one_host = RunChaosScan(Scan(dir, "one-host", 7795, 0));
  ASSERT_TRUE(one_host.error.empty()) << one_host.error;

  ChaosScanOptions split = Scan(dir, "two-hosts", 7797, 1);
  split.cell.cell_prefix = hosts.CellPrefix();
  split.cell.service_prefix = hosts.ServicePrefix();
  const auto [tx_before, rx_before] = hosts.CellLinkBytes();
  const ChaosScanResult two_hosts = RunChaosScan(split);
  ASSERT_TRUE(two_hosts.error.empty()) << two_hosts.error;
  const auto [tx_after, rx_after] = hosts.CellLinkBytes();

  const ChaosComparison comparison = CompareWithReference(one_host, two_hosts);
  EXPECT_TRUE(comparison.ok()) << fmt::format("{}", fmt::join(comparison.problems, "\n"));
  EXPECT_TRUE(comparison.mesh_identical);
  EXPECT_EQ(two_hosts.mesh_sha256, one_host.mesh_sha256);
  // The build job alone sends every kept image to the other host, and the model comes back.
  EXPECT_GT(tx_after - tx_before, 5'000'000) << "the jobs did not cross the link";
  EXPECT_GT(rx_after - rx_before, 1'000'000) << "the results did not cross the link";
  std::printf("[ measured ] one host %.1f s, two hosts %.1f s; link %.1f MB out, %.1f MB back\n",
              one_host.wall_s, two_hosts.wall_s, (tx_after - tx_before) * 1e-6,
              (rx_after - rx_before) * 1e-6);
}

}  // namespace
}  // namespace avc::bench
