#include "bench/devices/cell_processes.h"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdint>
#include <deque>
#include <fstream>
#include <stdexcept>

#include "core/launch/find_program.h"
#include "sim/cell/cell_fixtures.h"

namespace avc::bench {
namespace fs = std::filesystem;

std::string LogTail(const fs::path& log, int lines) {
  std::ifstream in(log);
  std::deque<std::string> tail;
  for (std::string line; std::getline(in, line);) {
    tail.push_back(line);
    if (static_cast<int>(tail.size()) > lines) tail.pop_front();
  }
  std::string out;
  for (const std::string& line : tail) out += line + "\n";
  return out;
}

namespace {

bool CanListenOn(int port) {
  // Close-on-exec: cells start their processes from several threads at once, and a probe socket
  // inherited by another thread's child stays bound in it, so the cell given that port could not
  // listen on it ("Address already in use", bench/chaos once in CI).
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw std::runtime_error("cannot create a socket to find a free port");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  const bool ok = bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  close(fd);
  return ok;
}

}  // namespace

int FreeTcpPort() {
  // Below the kernel's ephemeral range (32768-60999 by default), so no outgoing connection (a
  // driver dialling its device) takes the port before its server binds it. One cursor for the
  // process keeps cells started at once apart; the pid spreads processes. Spread by a large
  // prime, not taken as it is: test processes started one after another have consecutive pids,
  // and cursors a few ports apart overlap as soon as one process takes a few ports (a port found
  // free by two processes before either binds it: "Address already in use").
  constexpr int kFirst = 20000, kCount = 12000;
  constexpr uint64_t kSpread = 7919;
  static std::atomic<int> cursor{
      static_cast<int>(static_cast<uint64_t>(getpid()) * kSpread % kCount)};
  for (int tries = 0; tries < kCount; ++tries) {
    const int port = kFirst + cursor.fetch_add(1) % kCount;
    if (CanListenOn(port)) return port;
  }
  throw std::runtime_error(
      fmt::format("no free TCP port on 127.0.0.1 in {}-{}", kFirst, kFirst + kCount - 1));
}

CellProcessOptions LocalCellOptions(int port, const std::string& cell, double time_scale,
                                    const fs::path& work_dir) {
  CellProcessOptions options;
  options.avc_binary = launch::SelfExecutableDir() / "avc";
  options.work_dir = work_dir;
  options.lcm_url = fmt::format("udpm://239.255.76.67:{}?ttl=0", port);
  options.bulk_url = fmt::format("udpm://239.255.76.67:{}?ttl=0&recv_buf_size=4194304", port + 1);
  options.cell = cell;
  options.time_scale = time_scale;
  return options;
}

CellProcessOptions CellOptionsOnBus(const bus::BusOptions& bus, const fs::path& avc_binary,
                                    const fs::path& work_dir) {
  CellProcessOptions options;
  options.avc_binary = avc_binary;
  options.work_dir = work_dir;
  options.lcm_url = bus.control_url;
  options.bulk_url = bus.bulk_url;
  options.cell = bus.cell;
  return options;
}

bus::BusOptions ClientBusOptions(const CellProcessOptions& options, const std::string& source) {
  bus::BusOptions bus_options;
  bus_options.control_url = options.lcm_url;
  bus_options.bulk_url = options.bulk_url;
  bus_options.cell = options.cell;
  bus_options.source = source;
  return bus_options;
}

CellProcesses::CellProcesses(const CellProcessOptions& options)
    : work_dir_(options.work_dir),
      lcm_url_(options.lcm_url),
      bulk_url_(options.bulk_url),
      cell_(options.cell) {
  fs::create_directories(work_dir_);
  key_ = auth::LoadOrGenerateCommandKey(work_dir_ / "cell.key");
  const std::string key_file = key_.file.string();
  const std::string avc = options.avc_binary.string();
  const int rtde = FreeTcpPort(), primary = FreeTcpPort(), secondary = FreeTcpPort(),
            dashboard = FreeTcpPort(), camera = FreeTcpPort();
  const fs::path link_dir = work_dir_ / "sim";
  const std::vector<std::string>& on_cell = options.cell_prefix;
  if (options.record) {  // first, so it hears the others start
    fs::create_directories(recordings_dir());
    Start("avc-record", [this, avc, on_cell] {
      std::vector<std::string> argv = on_cell;
      argv.insert(argv.end(), {avc, "record", "-o", NextRecording().string()});
      return argv;
    });
  }
  std::vector<std::string> sim = {avc,
                                  "sim",
                                  "cell",
                                  "--plant",
                                  options.plant,
                                  "--triangles",
                                  std::to_string(options.triangles),
                                  "--width",
                                  std::to_string(options.width),
                                  "--height",
                                  std::to_string(options.height),
                                  "--time-scale",
                                  fmt::format("{}", options.time_scale),
                                  "--rtde-port",
                                  std::to_string(rtde),
                                  "--primary-port",
                                  std::to_string(primary),
                                  "--secondary-port",
                                  std::to_string(secondary),
                                  "--dashboard-port",
                                  std::to_string(dashboard),
                                  "--camera-port",
                                  std::to_string(camera),
                                  "--capture-latency",
                                  fmt::format("{}", options.capture_latency_s),
                                  "--table-speed",
                                  fmt::format("{}", options.table_speed_deg_s),
                                  "--link-dir",
                                  link_dir.string()};
  if (options.png) sim.push_back("--png");
  sim.insert(sim.end(), options.extra_sim_args.begin(), options.extra_sim_args.end());
  const auto fixed = [](const std::vector<std::string>& prefix, std::vector<std::string> argv) {
    argv.insert(argv.begin(), prefix.begin(), prefix.end());
    return [argv = std::move(argv)] { return argv; };
  };
  Start("avc-sim", fixed(on_cell, sim));
  // The bench and turntable as the lab measured them: every move is checked against them.
  std::vector<std::string> robot = {avc,
                                    "robot",
                                    "--host",
                                    "127.0.0.1",
                                    "--rtde-port",
                                    std::to_string(rtde),
                                    "--secondary-port",
                                    std::to_string(secondary),
                                    "--dashboard-port",
                                    std::to_string(dashboard),
                                    "--key",
                                    key_file};
  const std::vector<std::string> envelope = sim::RobotEnvelopeArguments(sim::NominalCellEnvelope());
  robot.insert(robot.end(), envelope.begin(), envelope.end());
  Start("avc-robot", fixed(on_cell, robot));
  Start("avc-turntable",
        fixed(on_cell, {avc, "turntable", "--device", (link_dir / "lt360").string(), "--speed",
                        fmt::format("{}", options.table_speed_deg_s), "--key", key_file}));
  Start("avc-camera",
        fixed(on_cell, {avc, "camera", "--port", fmt::format("ptpip:127.0.0.1:{}", camera),
                        "--no-usb-watch"}));
  if (options.stages) {
    for (const char* stage : {"planner", "builder", "clusterer", "surfacer"}) {
      const std::string name = fmt::format("avc-{}", stage);
      std::vector<std::string> argv = {avc, stage};
      if (const auto extra = options.service_args.find(name); extra != options.service_args.end()) {
        argv.insert(argv.end(), extra->second.begin(), extra->second.end());
      }
      Start(name, fixed(options.service_prefix, argv));
    }
  }
}

void CellProcesses::Start(const std::string& name, std::function<std::vector<std::string>()> argv) {
  const fs::path log = work_dir_ / (name + ".log");
  launch::ChildProcess child = Spawn(log, argv());
  processes_.push_back({name, log, std::move(argv), std::move(child)});
}

launch::ChildProcess CellProcesses::Spawn(const fs::path& log,
                                          std::vector<std::string> argv) const {
  launch::SpawnSpec spec;
  spec.argv = std::move(argv);
  spec.argv.insert(spec.argv.end(),
                   {"--lcm-url", lcm_url_, "--bulk-url", bulk_url_, "--cell", cell_});
  spec.log_file = log.string();
  spec.env["HOME"] = work_dir_.string();  // libgphoto2 keeps its settings under $HOME
  return launch::ChildProcess::Spawn(spec);
}

// `avc record` never overwrites a log: each start takes the next free number.
fs::path CellProcesses::NextRecording() const {
  for (int n = 1;; ++n) {
    const fs::path path = recordings_dir() / fmt::format("{}-{:03d}.lcmlog", cell_, n);
    if (!fs::exists(path)) return path;
  }
}

CellProcesses::~CellProcesses() {
  // Drivers first, so none of them sees its device vanish; the cell last.
  for (auto it = processes_.rbegin(); it != processes_.rend(); ++it) {
    it->child.Signal(SIGTERM);
    if (!it->child.WaitFor(std::chrono::milliseconds(5000))) it->child.Signal(SIGKILL);
  }
}

void CellProcesses::KillAndRestart(const std::string& name) {
  for (Process& process : processes_) {
    if (process.name != name) continue;
    process.child.Signal(SIGKILL);
    process.child.WaitFor(std::chrono::milliseconds(5000));
    process.child = Spawn(process.log, process.argv());
    return;
  }
  throw std::invalid_argument("no cell process named " + name);
}

std::vector<std::string> CellProcesses::Exited() {
  std::vector<std::string> exited;
  for (Process& process : processes_) {
    if (const auto status = process.child.TryWait()) {
      exited.push_back(process.name + " " + launch::DescribeWaitStatus(*status));
    }
  }
  return exited;
}

std::string CellProcesses::LogTails(int lines) const {
  std::string out;
  for (const Process& process : processes_) {
    out += fmt::format("--- {} ({})\n{}", process.name, process.log.string(),
                       LogTail(process.log, lines));
  }
  return out;
}

fs::path CellProcesses::truth_log() const { return work_dir_ / "sim" / "truth.jsonl"; }

}  // namespace avc::bench
