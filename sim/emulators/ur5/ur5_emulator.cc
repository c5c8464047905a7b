#include "sim/emulators/ur5/ur5_emulator.h"

#include <fmt/format.h>
#include <poll.h>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "core/net/tcp_socket.h"
#include "sim/emulators/ur5/ur5_controller.h"
#include "sim/emulators/ur5/ur5_dashboard_server.h"
#include "sim/emulators/ur5/ur5_primary_server.h"
#include "sim/emulators/ur5/ur5_rtde_server.h"

namespace avc::sim::ur5 {
namespace {

// Control ticks run back to back after a stall before the loop gives up catching up.
constexpr int kMaxCatchUpTicks = 20;

enum class Interface { kRtde, kPrimary, kSecondary, kDashboard };

}  // namespace

struct Ur5Emulator::Impl {
  Impl(Ur5EmulatorOptions opts, std::shared_ptr<EmulatorClock> shared_clock)
      : options(std::move(opts)),
        clock(shared_clock ? std::move(shared_clock) : std::make_shared<RealTimeEmulatorClock>()),
        rtde(options.host, options.rtde_port),
        primary(options.host, options.primary_port),
        secondary(options.host, options.secondary_port),
        dashboard(options.host, options.dashboard_port),
        controller(options, clock->NowSeconds()) {}

  net::TcpListener& Listener(Interface which) {
    switch (which) {
      case Interface::kRtde:
        return rtde;
      case Interface::kPrimary:
        return primary;
      case Interface::kSecondary:
        return secondary;
      default:
        return dashboard;
    }
  }

  void Accept(Interface which) {
    while (true) {
      net::TcpStream stream = Listener(which).Accept();
      if (!stream.is_open()) return;
      const int id = next_session_id++;
      if (which == Interface::kRtde) {
        sessions.push_back(
            std::make_unique<RtdeSession>(id, std::move(stream), controller, input_owners));
      } else if (which == Interface::kDashboard) {
        sessions.push_back(std::make_unique<DashboardSession>(id, std::move(stream), controller));
      } else {
        sessions.push_back(std::make_unique<PrimarySession>(id, std::move(stream), controller));
      }
    }
  }

  // Accepts and reads whatever is waiting, without blocking.
  void Serve() {
    constexpr Interface kInterfaces[] = {Interface::kRtde, Interface::kPrimary,
                                         Interface::kSecondary, Interface::kDashboard};
    std::vector<pollfd> fds;
    for (Interface which : kInterfaces) fds.push_back({Listener(which).fd(), POLLIN, 0});
    const size_t first_session = fds.size();
    for (const auto& session : sessions) fds.push_back({session->fd(), POLLIN, 0});
    if (poll(fds.data(), fds.size(), 0) <= 0) return;
    // Sessions first: the ones accepted below are not in `fds`.
    for (size_t i = first_session; i < fds.size(); ++i) {
      Session& session = *sessions[i - first_session];
      if (!session.closed() && (fds[i].revents & (POLLIN | POLLHUP | POLLERR))) {
        session.ReadAvailable();
      }
    }
    for (size_t i = 0; i < first_session; ++i) {
      if (fds[i].revents & POLLIN) Accept(kInterfaces[i]);
    }
  }

  // Runs the control ticks that are due on the clock.
  void TickDue() {
    int ticks = 0;
    while (ticks < kMaxCatchUpTicks && clock->NowSeconds() >= next_tick) {
      controller.Tick(next_tick);
      for (auto& session : sessions) {
        if (!session->closed()) session->OnTick();
      }
      next_tick += controller.dt();
      ++ticks;
    }
    if (ticks == kMaxCatchUpTicks) {
      const double now = clock->NowSeconds();
      if (now >= next_tick) next_tick = now + controller.dt();  // fell behind: skip ahead
    }
  }

  void DeliverAndFlush() {
    for (auto& message : controller.TakeMessages()) {
      for (auto& session : sessions) {
        if (session->id() == message.session_id && !session->closed()) {
          session->Queue(message.bytes);
        }
      }
    }
    for (auto& session : sessions) {
      if (drop_requested) session->Close();
      if (!session->closed()) session->Flush();
    }
    drop_requested = false;
    std::erase_if(sessions, [](const auto& session) { return session->closed(); });
  }

  void Loop() {
    next_tick = controller.time() + controller.dt();
    while (!stopping) {
      // Paced by the shared clock: at most one control period (of clock time) between rounds.
      clock->SleepUntil(next_tick);
      std::lock_guard lock(mutex);
      if (stopping) break;
      Serve();
      TickDue();
      DeliverAndFlush();
    }
    std::lock_guard lock(mutex);
    sessions.clear();
  }

  Ur5EmulatorOptions options;
  std::shared_ptr<EmulatorClock> clock;
  net::TcpListener rtde, primary, secondary, dashboard;
  Ur5Controller controller;
  RtdeInputOwners input_owners;
  std::vector<std::unique_ptr<Session>> sessions;
  int next_session_id = 1;
  double next_tick = 0;
  std::atomic<bool> stopping{false};
  bool drop_requested = false;
  mutable std::mutex mutex;
};

Ur5Emulator::Ur5Emulator(Ur5EmulatorOptions options, std::shared_ptr<EmulatorClock> clock) {
  if (auto error = options.Validate(); !error.empty()) {
    throw std::invalid_argument("UR5 emulator options: " + error);
  }
  impl_ = std::make_unique<Impl>(std::move(options), std::move(clock));
  thread_ = std::thread([this] { impl_->Loop(); });
}

Ur5Emulator::~Ur5Emulator() { Stop(); }

void Ur5Emulator::Stop() {
  if (!thread_.joinable()) return;
  impl_->stopping = true;
  thread_.join();
}

uint16_t Ur5Emulator::rtde_port() const { return impl_->rtde.port(); }
uint16_t Ur5Emulator::primary_port() const { return impl_->primary.port(); }
uint16_t Ur5Emulator::secondary_port() const { return impl_->secondary.port(); }
uint16_t Ur5Emulator::dashboard_port() const { return impl_->dashboard.port(); }

Ur5Snapshot Ur5Emulator::Snapshot() const {
  std::lock_guard lock(impl_->mutex);
  const Ur5Controller& controller = impl_->controller;
  Ur5Snapshot snapshot;
  snapshot.time = controller.time();
  snapshot.true_q = controller.true_q();
  snapshot.reported_q = controller.reported_q();
  snapshot.true_T_base_flange = controller.TrueBaseFromFlange();
  snapshot.robot_mode = controller.robot_mode();
  snapshot.safety_mode = controller.safety_mode();
  snapshot.program_running = controller.program_running();
  for (const auto& session : impl_->sessions) {
    if (const auto* rtde = dynamic_cast<const RtdeSession*>(session.get())) {
      snapshot.rtde_clients += rtde->streaming() ? 1 : 0;
    } else if (dynamic_cast<const PrimarySession*>(session.get()) != nullptr) {
      ++snapshot.script_clients;
    }
  }
  snapshot.scripts_run = controller.scripts_run();
  return snapshot;
}

Eigen::Isometry3d Ur5Emulator::TrueBaseFromFlange() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->controller.TrueBaseFromFlange();
}

void Ur5Emulator::TriggerProtectiveStop() {
  std::lock_guard lock(impl_->mutex);
  impl_->controller.ProtectiveStop();
}

void Ur5Emulator::ArmProtectiveStopAt(double fraction) {
  if (!(fraction >= 0 && fraction <= 1)) {
    throw std::invalid_argument(
        fmt::format("protective stop fraction {} is outside [0, 1]", fraction));
  }
  std::lock_guard lock(impl_->mutex);
  impl_->controller.ArmProtectiveStopAt(fraction);
}

void Ur5Emulator::DropConnections() {
  std::lock_guard lock(impl_->mutex);
  impl_->drop_requested = true;
}

}  // namespace avc::sim::ur5
