#include "sim/emulators/ur5/ur5_emulator.h"

#include <fmt/format.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/kinematics/forward_kinematics.h"
#include "drivers/robot/motion_monitor.h"
#include "drivers/robot/primary_protocol.h"
#include "drivers/robot/tcp_socket.h"
#include "sim/emulators/ur5/ur5_arm.h"
#include "sim/emulators/ur5/ur5_rtde_variables.h"
#include "sim/emulators/ur5/ur5_script.h"

namespace avc::sim::ur5 {
namespace {

namespace rtde = robot::rtde;
using robot::RobotMode;
using robot::SafetyMode;
using Clock = std::chrono::steady_clock;

// Output bytes a slow client may have queued before data packages are dropped (coalescing:
// it then gets the newest state when it catches up, and the queue never grows without bound).
constexpr size_t kMaxQueuedBytes = 64 * 1024;
constexpr int kMaxCatchUpTicks = 20;

std::string Lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string Trim(const std::string& text) {
  const size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return {};
  const size_t end = text.find_last_not_of(" \t\r\n");
  return text.substr(begin, end - begin + 1);
}

std::array<double, 6> ToArray(const kinematics::JointVector& v) {
  return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

constexpr double kSecondaryStatePeriod = 0.1;
// Deceleration (rad/s^2 along the path) when a new program aborts a moving one.
constexpr double kPreemptDeceleration = 4.0;

// KINEMATICS_INFO of the true arm; each joint's checksum is an FNV-1a hash of its four DH
// values, so it changes exactly when that joint's calibration does.
robot::primary::KinematicsInfo KinematicsOf(const kinematics::DhParameters& dh) {
  robot::primary::KinematicsInfo info;
  for (int i = 0; i < 6; ++i) {
    info.theta[i] = dh.theta_offset[i];
    info.a[i] = dh.a[i];
    info.d[i] = dh.d[i];
    info.alpha[i] = dh.alpha[i];
    uint32_t hash = 2166136261u;
    for (double value : {dh.theta_offset[i], dh.a[i], dh.d[i], dh.alpha[i]}) {
      const auto bits = std::bit_cast<uint64_t>(value);
      for (int byte = 0; byte < 8; ++byte) {
        hash = (hash ^ static_cast<uint8_t>(bits >> (8 * byte))) * 16777619u;
      }
    }
    info.checksum[i] = hash;
  }
  info.calibration_status = 1;
  return info;
}

enum class Service { kRtde, kSecondary, kDashboard };

struct InputRecipe {
  std::vector<std::string> names;
  std::vector<rtde::ValueType> types;
};

struct Connection {
  int id = 0;
  Service service = Service::kRtde;
  robot::TcpStream stream;
  std::vector<uint8_t> out;
  bool closed = false;
  bool closed_after_flush = false;  // dashboard "quit": hang up once the reply is out
  // RTDE
  rtde::PacketFramer framer;
  int protocol = 1;
  std::vector<std::string> output_names;
  std::vector<rtde::ValueType> output_types;
  double period = 0;  // simulated seconds between data packages
  double since_last = 0;
  bool started = false;
  std::map<uint8_t, InputRecipe> inputs;
  uint8_t next_input_id = 1;
  // Dashboard and secondary
  std::string line_buffer;
  ScriptAssembler assembler;
};

struct Program {
  std::vector<ScriptStatement> statements;
  size_t next = 0;
  int connection_id = 0;
};

}  // namespace

std::string Ur5EmulatorOptions::Validate() const {
  if (auto error = cell.Validate(); !error.empty()) return "cell: " + error;
  if (max_protocol_version < 1 || max_protocol_version > 2) {
    return fmt::format("max_protocol_version {} is not 1 or 2", max_protocol_version);
  }
  if (!(control_frequency > 0 && control_frequency <= 1000)) {
    return fmt::format("control_frequency {} is outside (0, 1000] Hz", control_frequency);
  }
  if (!(time_scale > 0 && time_scale <= 1000)) {
    return fmt::format("time_scale {} is outside (0, 1000]", time_scale);
  }
  if (!(encoder_noise_rad >= 0 && encoder_noise_rad < 0.01)) {
    return fmt::format("encoder_noise_rad {} is outside [0, 0.01)", encoder_noise_rad);
  }
  if (auto error = kinematics::ValidateJoints(initial_q); !error.empty()) {
    return "initial_q: " + error;
  }
  return {};
}

struct Ur5Emulator::Impl {
  explicit Impl(Ur5EmulatorOptions opts)
      : options(std::move(opts)),
        rtde_listener(options.host, options.rtde_port),
        secondary_listener(options.host, options.secondary_port),
        dashboard_listener(options.host, options.dashboard_port),
        arm(options.cell.dh, options.initial_q),
        rng(options.seed) {
    if (pipe(wake) != 0) throw std::runtime_error("UR5 emulator: pipe() failed");
    robot_mode = options.powered ? RobotMode::kRunning : RobotMode::kPowerOff;
    dt = 1.0 / options.control_frequency;
    kinematics_state = robot::primary::EncodeKinematicsState(KinematicsOf(options.cell.dh));
    UpdateControllerState();
  }

  ~Impl() {
    close(wake[0]);
    close(wake[1]);
  }

  void Wake() const {
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = write(wake[1], &byte, 1);
  }

  // --- Output -----------------------------------------------------------------------------

  void Queue(Connection& c, const std::vector<uint8_t>& bytes) {
    c.out.insert(c.out.end(), bytes.begin(), bytes.end());
  }
  void Queue(Connection& c, const std::string& text) {
    c.out.insert(c.out.end(), text.begin(), text.end());
  }
  void QueueRtde(Connection& c, rtde::PacketType type, const std::vector<uint8_t>& payload) {
    Queue(c, rtde::EncodePacket(type, payload));
  }
  void QueueRtdeText(Connection& c, const std::string& text, rtde::MessageLevel level) {
    QueueRtde(c, rtde::PacketType::kTextMessage,
              rtde::EncodeTextMessage({text.substr(0, 255), "RTDE", level}, c.protocol));
  }

  void Flush(Connection& c) {
    while (!c.out.empty() && !c.closed) {
      const ssize_t n = send(c.stream.fd(), c.out.data(), c.out.size(), MSG_NOSIGNAL);
      if (n > 0) {
        c.out.erase(c.out.begin(), c.out.begin() + n);
      } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
        return;
      } else if (n < 0 && errno == EINTR) {
        continue;
      } else {
        c.closed = true;
      }
    }
  }

  // --- RTDE -------------------------------------------------------------------------------

  void HandleRtde(Connection& c, const rtde::Packet& packet) {
    switch (static_cast<rtde::PacketType>(packet.type)) {
      case rtde::PacketType::kRequestProtocolVersion: {
        const uint16_t version = rtde::DecodeProtocolVersionRequest(packet.payload);
        const bool accepted = version >= 1 && version <= options.max_protocol_version;
        if (accepted) c.protocol = version;
        QueueRtde(c, rtde::PacketType::kRequestProtocolVersion, rtde::EncodeAccepted(accepted));
        return;
      }
      case rtde::PacketType::kGetUrcontrolVersion:
        QueueRtde(c, rtde::PacketType::kGetUrcontrolVersion,
                  rtde::EncodeControllerVersion(options.version));
        return;
      case rtde::PacketType::kSetupOutputs:
        SetupOutputs(c, rtde::DecodeSetupOutputsRequest(packet.payload, c.protocol));
        return;
      case rtde::PacketType::kSetupInputs:
        SetupInputs(c, rtde::DecodeSetupInputsRequest(packet.payload));
        return;
      case rtde::PacketType::kStart:
        c.started = !c.output_names.empty();
        c.since_last = c.period;  // first package at the next tick
        QueueRtde(c, rtde::PacketType::kStart, rtde::EncodeAccepted(c.started));
        return;
      case rtde::PacketType::kPause:
        c.started = false;
        QueueRtde(c, rtde::PacketType::kPause, rtde::EncodeAccepted(true));
        return;
      case rtde::PacketType::kDataPackage:
        WriteInputs(c, packet.payload);
        return;
      default:
        QueueRtdeText(c,
                      fmt::format("unsupported RTDE packet {}", rtde::PacketTypeName(packet.type)),
                      rtde::MessageLevel::kError);
    }
  }

  void SetupOutputs(Connection& c, const rtde::SetupOutputsRequest& request) {
    rtde::RecipeReply reply;
    std::vector<rtde::ValueType> types;
    bool all_found = true;
    for (const auto& name : request.names) {
      const auto type = OutputType(name);
      all_found = all_found && type.has_value();
      reply.types.emplace_back(type ? rtde::ValueTypeName(*type) : "NOT_FOUND");
      if (type) types.push_back(*type);
    }
    const bool frequency_ok =
        request.frequency > 0 && request.frequency <= options.control_frequency;
    if (!frequency_ok) {
      QueueRtdeText(c,
                    fmt::format("output frequency {} Hz is outside (0, {}]", request.frequency,
                                options.control_frequency),
                    rtde::MessageLevel::kError);
    }
    if (all_found && frequency_ok && !request.names.empty()) {
      reply.recipe_id = 1;
      c.output_names = request.names;
      c.output_types = std::move(types);
      c.period = 1.0 / request.frequency;
    }
    QueueRtde(c, rtde::PacketType::kSetupOutputs, rtde::EncodeRecipeReply(reply));
  }

  void SetupInputs(Connection& c, const std::vector<std::string>& names) {
    rtde::RecipeReply reply;
    InputRecipe recipe;
    bool usable = !names.empty();
    for (const auto& name : names) {
      const auto type = InputType(name);
      const auto owner = input_owner.find(name);
      if (!type) {
        reply.types.emplace_back("NOT_FOUND");
        usable = false;
      } else if (owner != input_owner.end() && owner->second != c.id) {
        reply.types.emplace_back("IN_USE");
        usable = false;
      } else {
        reply.types.emplace_back(rtde::ValueTypeName(*type));
        recipe.names.push_back(name);
        recipe.types.push_back(*type);
      }
    }
    if (usable) {
      reply.recipe_id = c.next_input_id++;
      for (const auto& name : names) input_owner[name] = c.id;
      c.inputs[reply.recipe_id] = std::move(recipe);
    }
    QueueRtde(c, rtde::PacketType::kSetupInputs, rtde::EncodeRecipeReply(reply));
  }

  void WriteInputs(Connection& c, const std::vector<uint8_t>& payload) {
    // v1 packages carry no recipe id: they belong to the only input recipe.
    const uint8_t id = c.protocol >= 2 && !payload.empty() ? payload[0] : 1;
    const auto recipe = c.inputs.find(id);
    if (recipe == c.inputs.end()) {
      QueueRtdeText(c, fmt::format("data package for unknown input recipe {}", id),
                    rtde::MessageLevel::kError);
      return;
    }
    const auto package = rtde::DecodeDataPackage(payload, recipe->second.types, c.protocol);
    for (size_t i = 0; i < package.values.size(); ++i) {
      WriteInput(recipe->second.names[i], package.values[i], controller);
    }
  }

  void EmitRtde(Connection& c) {
    if (!c.started) return;
    c.since_last += dt;
    if (c.since_last + 1e-9 < c.period) return;
    c.since_last = std::min(c.since_last - c.period, c.period);
    if (c.out.size() > kMaxQueuedBytes) return;  // slow client: drop, do not queue
    rtde::DataPackage package;
    package.recipe_id = 1;
    for (const auto& name : c.output_names) package.values.push_back(OutputValue(name, controller));
    QueueRtde(c, rtde::PacketType::kDataPackage,
              rtde::EncodeDataPackage(package, c.output_types, c.protocol));
  }

  // --- Dashboard --------------------------------------------------------------------------

  std::string Dashboard(Connection& c, const std::string& raw) {
    const std::string command = Lower(Trim(raw));
    if (command == "power on") {
      if (robot_mode == RobotMode::kPowerOff) robot_mode = RobotMode::kIdle;
      return "Powering on";
    }
    if (command == "power off") {
      robot_mode = RobotMode::kPowerOff;
      AbortProgram();
      arm.Halt();
      return "Powering off";
    }
    if (command == "brake release") {
      if (robot_mode == RobotMode::kIdle) robot_mode = RobotMode::kRunning;
      return "Brake releasing";
    }
    if (command == "robotmode") return fmt::format("Robotmode: {}", RobotModeName(robot_mode));
    if (command == "safetymode") {
      return fmt::format("Safetymode: {}", SafetyModeName(safety_mode));
    }
    if (command == "safetystatus") {
      return fmt::format("Safetystatus: {}", SafetyModeName(safety_mode));
    }
    if (command == "unlock protective stop") {
      if (safety_mode != SafetyMode::kProtectiveStop) {
        return "Cannot unlock protective stop, robot is not protective stopped";
      }
      safety_mode = SafetyMode::kNormal;
      return "Protective stop releasing";
    }
    if (command == "close safety popup") return "closing safety popup";
    if (command == "close popup") return "closing popup";
    if (command == "polyscopeversion") {
      return fmt::format("URSoftware {}.{}.{}.{} (emulated)", options.version.major,
                         options.version.minor, options.version.bugfix, options.version.build);
    }
    if (command == "get robot model") return "UR5";
    if (command == "get serial number") return "EMULATED-UR5";
    if (command == "running") {
      return fmt::format("Program running: {}", program ? "true" : "false");
    }
    if (command == "programstate") return program ? "PLAYING avc" : "STOPPED <unnamed>";
    if (command == "stop") {
      AbortProgram();
      arm.Brake(2.0);
      return "Stopped";
    }
    if (command == "quit") {
      c.closed_after_flush = true;
      return "Disconnected";
    }
    return fmt::format("could not understand: '{}'", Trim(raw));
  }

  // --- Secondary (scripts) ----------------------------------------------------------------

  void RuntimeError(int connection_id, int line, int column, const std::string& text) {
    ++runtime_errors;
    for (auto& c : connections) {
      if (c->id != connection_id || c->closed) continue;
      robot::primary::RobotMessage message;
      message.timestamp = static_cast<uint64_t>(time * 1e6);
      message.message_type = robot::primary::kRuntimeException;
      message.line = line;
      message.column = column;
      message.text = text;
      Queue(*c, robot::primary::EncodeRobotMessage(message));
    }
  }

  void RunScript(Connection& c, const std::vector<std::string>& lines) {
    const ScriptProgram parsed = ParseScriptUnit(lines);
    if (parsed.error) {
      RuntimeError(c.id, parsed.error->line, parsed.error->column, parsed.error->text);
      return;
    }
    if (robot_mode != RobotMode::kRunning || safety_mode != SafetyMode::kNormal) {
      RuntimeError(c.id, 1, 1,
                   fmt::format("cannot run program: robot mode {}, safety mode {}",
                               RobotModeName(robot_mode), SafetyModeName(safety_mode)));
      return;
    }
    ++scripts_run;
    // A new program aborts the running one: the arm brakes to rest (at the new program's own
    // stopj deceleration when it starts with one) before the new motions begin.
    program = Program{parsed.statements, 0, c.id};
    if (arm.moving() && (parsed.statements.empty() ||
                         parsed.statements.front().kind != ScriptStatement::Kind::kStopJ)) {
      arm.Brake(kPreemptDeceleration);
    }
    AdvanceProgram();
  }

  void AbortProgram() { program.reset(); }

  // Starts statements until one moves the arm or the program ends.
  void AdvanceProgram() {
    while (program && program->next < program->statements.size()) {
      const ScriptStatement& s = program->statements[program->next];
      // stopj acts at once, even on a moving arm; motions wait until the arm is still.
      if (s.kind != ScriptStatement::Kind::kStopJ && arm.moving()) break;
      ++program->next;
      std::string error;
      switch (s.kind) {
        case ScriptStatement::Kind::kMoveJ:
          error = s.target_is_pose
                      ? arm.StartMoveJToPose(robot::PoseFromVector(s.target), s.acceleration,
                                             s.velocity)
                      : arm.StartMoveJ(Eigen::Map<const kinematics::JointVector>(s.target.data()),
                                       s.acceleration, s.velocity);
          break;
        case ScriptStatement::Kind::kMoveL:
          error = arm.StartMoveL(robot::PoseFromVector(s.target), s.acceleration, s.velocity);
          break;
        case ScriptStatement::Kind::kStopJ:
          arm.Brake(s.acceleration);
          break;
      }
      if (!error.empty()) {
        RuntimeError(program->connection_id, s.line, 1, error);
        AbortProgram();
        arm.Halt();
      }
    }
    // stopj inside a program lets the arm brake to a halt before the program ends.
    if (program && program->next >= program->statements.size() && !arm.moving()) AbortProgram();
  }

  void ProtectiveStop() {
    safety_mode = SafetyMode::kProtectiveStop;
    arm.Halt();
    AbortProgram();
  }

  // --- Control tick -----------------------------------------------------------------------

  double Noise() {
    // Own mapping from 53 random bits: identical across standard libraries.
    const double unit = static_cast<double>(rng() >> 11) * 0x1.0p-53;
    return (2 * unit - 1) * options.encoder_noise_rad;
  }

  void UpdateControllerState() {
    for (int i = 0; i < 6; ++i) reported_q[i] = arm.q()[i] + Noise();
    controller.timestamp = time;
    controller.actual_q = ToArray(reported_q);
    controller.actual_qd = ToArray(arm.qd());
    controller.target_q = ToArray(arm.target_q());
    controller.target_qd = ToArray(arm.qd());
    // The controller computes the TCP from its encoders through its own (true) kinematics.
    controller.actual_tcp_pose =
        robot::VectorFromPose(kinematics::ForwardKinematics(options.cell.dh, reported_q));
    controller.target_tcp_pose =
        robot::VectorFromPose(kinematics::ForwardKinematics(options.cell.dh, arm.target_q()));
    controller.robot_mode = static_cast<int32_t>(robot_mode);
    controller.safety_mode = static_cast<int32_t>(safety_mode);
    controller.safety_status_bits = safety_mode == SafetyMode::kNormal
                                        ? robot::kSafetyNormal
                                        : (safety_mode == SafetyMode::kProtectiveStop
                                               ? (robot::kSafetyProtectiveStopped | (1u << 10))
                                               : (1u << 10));
    const bool running = program.has_value();
    controller.runtime_state = static_cast<uint32_t>(running ? robot::RuntimeState::kPlaying
                                                             : robot::RuntimeState::kStopped);
    const bool powered = robot_mode == RobotMode::kPowerOn || robot_mode == RobotMode::kIdle ||
                         robot_mode == RobotMode::kRunning || robot_mode == RobotMode::kBackdrive;
    controller.robot_status_bits =
        (powered ? robot::kStatusPowerOn : 0u) | (running ? robot::kStatusProgramRunning : 0u);
  }

  void Tick() {
    AdvanceProgram();
    if (const std::string error = arm.Step(dt); !error.empty()) {
      if (program) RuntimeError(program->connection_id, 0, 0, error);
      AbortProgram();
    }
    if (stop_at_fraction && arm.moving() && arm.progress() >= *stop_at_fraction) {
      stop_at_fraction.reset();
      ProtectiveStop();
    }
    AdvanceProgram();
    time += dt;
    UpdateControllerState();
    for (auto& c : connections) {
      if (c->service == Service::kRtde && !c->closed) EmitRtde(*c);
    }
    // The secondary interface's 10 Hz ROBOT_STATE stream (here: KINEMATICS_INFO only).
    since_secondary_state += dt;
    if (since_secondary_state + 1e-9 >= kSecondaryStatePeriod) {
      since_secondary_state = 0;
      for (auto& c : connections) {
        if (c->service == Service::kSecondary && !c->closed && c->out.size() < kMaxQueuedBytes) {
          Queue(*c, kinematics_state);
        }
      }
    }
  }

  // --- Loop -------------------------------------------------------------------------------

  void Accept(robot::TcpListener& listener, Service service) {
    while (true) {
      robot::TcpStream stream = listener.Accept();
      if (!stream.is_open()) return;
      auto c = std::make_unique<Connection>();
      c->id = next_connection_id++;
      c->service = service;
      c->stream = std::move(stream);
      if (service == Service::kDashboard) {
        Queue(*c, std::string("Connected: Universal Robots Dashboard Server\n"));
      }
      if (service == Service::kSecondary) {
        const robot::primary::VersionMessage version{"URControl",
                                                     static_cast<uint8_t>(options.version.major),
                                                     static_cast<uint8_t>(options.version.minor),
                                                     static_cast<int32_t>(options.version.bugfix),
                                                     static_cast<int32_t>(options.version.build),
                                                     "emulated"};
        Queue(*c, robot::primary::EncodeVersionMessage(version, static_cast<uint64_t>(time * 1e6)));
        Queue(*c, kinematics_state);
      }
      connections.push_back(std::move(c));
    }
  }

  void Read(Connection& c) {
    uint8_t buffer[8192];
    while (!c.closed) {
      const ssize_t n = recv(c.stream.fd(), buffer, sizeof(buffer), 0);
      if (n == 0) {
        c.closed = true;
        return;
      }
      if (n < 0) {
        if (errno == EINTR) continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK) c.closed = true;
        return;
      }
      try {
        Process(c, buffer, static_cast<size_t>(n));
      } catch (const std::exception& error) {
        // A malformed packet from a client: tell it, then hang up (the stream cannot resync).
        if (c.service == Service::kRtde) {
          QueueRtdeText(c, error.what(), rtde::MessageLevel::kException);
        }
        Flush(c);
        c.closed = true;
      }
    }
  }

  void Process(Connection& c, const uint8_t* data, size_t size) {
    if (c.service == Service::kRtde) {
      c.framer.Append(data, size);
      while (auto packet = c.framer.Next()) HandleRtde(c, *packet);
      return;
    }
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (c.service == Service::kSecondary) {
      c.assembler.Append(text);
      while (auto unit = c.assembler.Next()) RunScript(c, *unit);
      return;
    }
    c.line_buffer += text;
    size_t end;
    while ((end = c.line_buffer.find('\n')) != std::string::npos) {
      const std::string line = c.line_buffer.substr(0, end);
      c.line_buffer.erase(0, end + 1);
      Queue(c, Dashboard(c, line) + "\n");
    }
  }

  void CloseConnection(Connection& c) {
    for (auto it = input_owner.begin(); it != input_owner.end();) {
      it = it->second == c.id ? input_owner.erase(it) : std::next(it);
    }
    c.stream.Close();
  }

  void Loop() {
    using Seconds = std::chrono::duration<double>;
    const auto real_tick =
        std::chrono::duration_cast<Clock::duration>(Seconds(dt / options.time_scale));
    auto next_tick = Clock::now() + real_tick;
    std::vector<pollfd> fds;
    while (true) {
      {
        std::lock_guard lock(mutex);
        if (stopping) break;
        fds.clear();
        fds.push_back({wake[0], POLLIN, 0});
        fds.push_back({rtde_listener.fd(), POLLIN, 0});
        fds.push_back({secondary_listener.fd(), POLLIN, 0});
        fds.push_back({dashboard_listener.fd(), POLLIN, 0});
        for (auto& c : connections) {
          const short events = static_cast<short>(POLLIN | (c->out.empty() ? 0 : POLLOUT));
          fds.push_back({c->stream.fd(), events, 0});
        }
      }
      const auto wait = std::max(Clock::duration::zero(), next_tick - Clock::now());
      const auto wait_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(wait).count();
      timespec timeout{static_cast<time_t>(wait_ns / 1000000000),
                       static_cast<long>(wait_ns % 1000000000)};
      ppoll(fds.data(), fds.size(), &timeout, nullptr);

      std::lock_guard lock(mutex);
      if (fds[0].revents & POLLIN) {
        char drain[64];
        [[maybe_unused]] const ssize_t n = read(wake[0], drain, sizeof(drain));
      }
      if (stopping) break;
      if (drop_requested) {
        for (auto& c : connections) c->closed = true;
        drop_requested = false;
      }
      if (fds[1].revents & POLLIN) Accept(rtde_listener, Service::kRtde);
      if (fds[2].revents & POLLIN) Accept(secondary_listener, Service::kSecondary);
      if (fds[3].revents & POLLIN) Accept(dashboard_listener, Service::kDashboard);
      // Connections accepted just now are past the end of `fds`.
      for (size_t i = 4; i < fds.size() && i - 4 < connections.size(); ++i) {
        Connection& c = *connections[i - 4];
        if (c.closed) continue;
        if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) Read(c);
      }
      int ticks = 0;
      while (Clock::now() >= next_tick && ticks < kMaxCatchUpTicks) {
        Tick();
        next_tick += real_tick;
        ++ticks;
      }
      if (Clock::now() >= next_tick) next_tick = Clock::now() + real_tick;  // fell behind
      for (auto& c : connections) {
        if (!c->closed) Flush(*c);
        if (c->closed_after_flush && c->out.empty()) c->closed = true;
      }
      for (auto it = connections.begin(); it != connections.end();) {
        if ((*it)->closed) {
          CloseConnection(**it);
          it = connections.erase(it);
        } else {
          ++it;
        }
      }
    }
    std::lock_guard lock(mutex);
    for (auto& c : connections) CloseConnection(*c);
    connections.clear();
  }

  Ur5EmulatorOptions options;
  robot::TcpListener rtde_listener, secondary_listener, dashboard_listener;
  Ur5Arm arm;
  std::mt19937_64 rng;
  int wake[2] = {-1, -1};
  double dt = 0.008;
  double time = 0;
  double since_secondary_state = 0;
  std::vector<uint8_t> kinematics_state;  // encoded once: the true arm never changes
  RobotMode robot_mode = RobotMode::kPowerOff;
  SafetyMode safety_mode = SafetyMode::kNormal;
  kinematics::JointVector reported_q = kinematics::JointVector::Zero();
  ControllerState controller;
  std::optional<Program> program;
  std::optional<double> stop_at_fraction;
  std::vector<std::unique_ptr<Connection>> connections;
  std::map<std::string, int> input_owner;
  int next_connection_id = 1;
  int scripts_run = 0;
  int runtime_errors = 0;
  bool stopping = false;
  bool drop_requested = false;
  mutable std::mutex mutex;
};

Ur5Emulator::Ur5Emulator(Ur5EmulatorOptions options) {
  if (auto error = options.Validate(); !error.empty()) {
    throw std::invalid_argument("UR5 emulator options: " + error);
  }
  impl_ = std::make_unique<Impl>(std::move(options));
  thread_ = std::thread([this] { impl_->Loop(); });
}

Ur5Emulator::~Ur5Emulator() { Stop(); }

void Ur5Emulator::Stop() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(impl_->mutex);
    impl_->stopping = true;
  }
  impl_->Wake();
  thread_.join();
}

uint16_t Ur5Emulator::rtde_port() const { return impl_->rtde_listener.port(); }
uint16_t Ur5Emulator::secondary_port() const { return impl_->secondary_listener.port(); }
uint16_t Ur5Emulator::dashboard_port() const { return impl_->dashboard_listener.port(); }

Ur5Snapshot Ur5Emulator::Snapshot() const {
  std::lock_guard lock(impl_->mutex);
  Ur5Snapshot snapshot;
  snapshot.time = impl_->time;
  snapshot.true_q = impl_->arm.q();
  snapshot.reported_q = impl_->reported_q;
  snapshot.robot_mode = impl_->robot_mode;
  snapshot.safety_mode = impl_->safety_mode;
  snapshot.program_running = impl_->program.has_value();
  for (const auto& c : impl_->connections) {
    if (c->service == Service::kRtde && c->started) ++snapshot.rtde_clients;
  }
  snapshot.scripts_run = impl_->scripts_run;
  return snapshot;
}

void Ur5Emulator::TriggerProtectiveStop() {
  std::lock_guard lock(impl_->mutex);
  impl_->ProtectiveStop();
}

void Ur5Emulator::ArmProtectiveStopAt(double fraction) {
  if (!(fraction >= 0 && fraction <= 1)) {
    throw std::invalid_argument(
        fmt::format("protective stop fraction {} is outside [0, 1]", fraction));
  }
  std::lock_guard lock(impl_->mutex);
  impl_->stop_at_fraction = fraction;
}

void Ur5Emulator::DropConnections() {
  {
    std::lock_guard lock(impl_->mutex);
    impl_->drop_requested = true;
  }
  impl_->Wake();
}

}  // namespace avc::sim::ur5
