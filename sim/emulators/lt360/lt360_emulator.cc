#include "sim/emulators/lt360/lt360_emulator.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "core/util/keyed_random.h"

namespace avc::sim {
namespace {

using turntable::CommandKind;

double WrapDeg(double deg) {
  const double wrapped = std::fmod(deg, 360.0);
  return wrapped < 0 ? wrapped + 360.0 : wrapped;
}

// Reported angle: nearest tenth of the wrapped position, in [0, 3600).
int QuantiseTenths(double deg) {
  const long tenths = std::lround(WrapDeg(deg) * 10);
  return static_cast<int>(tenths % 3600);
}

}  // namespace

double TravelledDeg(double distance, double speed, double accel, double t) {
  if (accel <= 0) return std::min(distance, speed * t);
  // Trapezoidal profile; triangular when the move is too short to reach full speed.
  const double ramp_s = speed / accel;
  const double ramp_deg = 0.5 * accel * ramp_s * ramp_s;
  if (2 * ramp_deg >= distance) {
    const double half_s = std::sqrt(distance / accel);
    if (t <= half_s) return 0.5 * accel * t * t;
    const double left_s = std::max(0.0, 2 * half_s - t);
    return distance - 0.5 * accel * left_s * left_s;
  }
  const double end_s = 2 * ramp_s + (distance - 2 * ramp_deg) / speed;
  if (t <= ramp_s) return 0.5 * accel * t * t;
  if (t <= end_s - ramp_s) return ramp_deg + speed * (t - ramp_s);
  const double left_s = std::max(0.0, end_s - t);
  return distance - 0.5 * accel * left_s * left_s;
}

namespace {

std::runtime_error PtyError(const std::string& what) {
  return std::runtime_error(fmt::format("LT360 emulator: {}: {}", what, std::strerror(errno)));
}

}  // namespace

std::string Lt360EmulatorOptions::Validate() const {
  if (!(speed_deg_s > 0) || !std::isfinite(speed_deg_s)) {
    return fmt::format("LT360 emulator: speed must be > 0 deg/s, got {}", speed_deg_s);
  }
  if (!std::isfinite(start_deg) || !std::isfinite(offset_deg) || !std::isfinite(scale_error) ||
      !(sigma_deg >= 0) || !(accel_deg_s2 >= 0) || !std::isfinite(accel_deg_s2)) {
    return "LT360 emulator: start, offset and scale must be finite, sigma and accel >= 0";
  }
  return table.Validate();
}

Lt360Emulator::Lt360Emulator(Lt360EmulatorOptions options, std::shared_ptr<EmulatorClock> clock)
    : options_(std::move(options)),
      clock_(clock ? std::move(clock) : std::make_shared<RealTimeEmulatorClock>()),
      position_deg_(options_.start_deg),
      speed_deg_s_(options_.speed_deg_s) {
  const std::string problem = options_.Validate();
  if (!problem.empty()) throw std::invalid_argument(problem);
  master_fd_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (master_fd_ < 0) throw PtyError("posix_openpt");
  char name[128];
  if (::grantpt(master_fd_) != 0 || ::unlockpt(master_fd_) != 0 ||
      ::ptsname_r(master_fd_, name, sizeof(name)) != 0) {
    const auto error = PtyError("grantpt/unlockpt/ptsname");
    ::close(master_fd_);
    throw error;
  }
  device_path_ = name;
  slave_fd_ = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
  termios tio{};
  if (slave_fd_ < 0 || ::tcgetattr(slave_fd_, &tio) != 0) {
    const auto error = PtyError("open " + device_path_);
    ::close(master_fd_);
    if (slave_fd_ >= 0) ::close(slave_fd_);
    throw error;
  }
  // Raw until the driver configures it: no echo of commands back to the driver.
  ::cfmakeraw(&tio);
  ::tcsetattr(slave_fd_, TCSANOW, &tio);
  ::fcntl(master_fd_, F_SETFL, ::fcntl(master_fd_, F_GETFL) | O_NONBLOCK);
  stop_fd_ = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  if (stop_fd_ < 0) {
    const auto error = PtyError("eventfd");
    ::close(master_fd_);
    ::close(slave_fd_);
    throw error;
  }
  thread_ = std::thread([this] { Serve(); });
}

Lt360Emulator::~Lt360Emulator() {
  const uint64_t one = 1;
  [[maybe_unused]] const ssize_t n = ::write(stop_fd_, &one, sizeof(one));
  if (thread_.joinable()) thread_.join();
  ::close(stop_fd_);
  std::lock_guard lock(mutex_);
  if (master_fd_ >= 0) ::close(master_fd_);
  if (slave_fd_ >= 0) ::close(slave_fd_);
}

void Lt360Emulator::Disconnect() {
  std::lock_guard lock(mutex_);
  if (slave_fd_ >= 0) ::close(slave_fd_);
  if (master_fd_ >= 0) ::close(master_fd_);
  slave_fd_ = master_fd_ = -1;
}

void Lt360Emulator::InjectFault(Lt360Fault fault, int replies) {
  std::lock_guard lock(mutex_);
  if (fault == Lt360Fault::kStall) {
    stalled_ = true;
    return;
  }
  fault_ = fault;
  fault_replies_ = replies;
}

void Lt360Emulator::ClearFaults() {
  const double now = clock_->NowSeconds();
  std::lock_guard lock(mutex_);
  Advance(now);
  if (stalled_ && move_) {
    // Resume from where it stuck.
    move_->from_deg = position_deg_;
    move_->start_s = now;
  }
  stalled_ = false;
  fault_ = Lt360Fault::kNone;
  fault_replies_ = 0;
}

int Lt360Emulator::ReportedTenths() const {
  std::lock_guard lock(mutex_);
  return QuantiseTenths(position_deg_);
}

double Lt360Emulator::TrueAngleDeg() const {
  std::lock_guard lock(mutex_);
  const double reported = QuantiseTenths(position_deg_) / 10.0;
  return WrapDeg(reported * (1 + options_.scale_error) + options_.offset_deg + move_noise_deg_);
}

bool Lt360Emulator::moving() const {
  std::lock_guard lock(mutex_);
  return move_ != nullptr;
}

double Lt360Emulator::speed_deg_s() const {
  std::lock_guard lock(mutex_);
  return speed_deg_s_;
}

int64_t Lt360Emulator::commands_served() const {
  std::lock_guard lock(mutex_);
  return commands_served_;
}

int64_t Lt360Emulator::moves_started() const {
  std::lock_guard lock(mutex_);
  return moves_started_;
}

void Lt360Emulator::Advance(double now_s) {
  if (!move_ || stalled_) return;
  const double travel = move_->to_deg - move_->from_deg;
  const double covered = TravelledDeg(std::abs(travel), speed_deg_s_, options_.accel_deg_s2,
                                      std::max(0.0, now_s - move_->start_s));
  if (covered >= std::abs(travel)) {
    position_deg_ = move_->to_deg;
    move_.reset();
    return;
  }
  position_deg_ = move_->from_deg + std::copysign(covered, travel);
}

void Lt360Emulator::StartMove(double delta_deg, double now_s) {
  ++moves_started_;
  // The error belongs to the target position, not to the move's place in the sequence: a goto
  // sent again after a restart lands on the same true angle.
  const auto target_tenths = static_cast<uint64_t>(QuantiseTenths(position_deg_ + delta_deg));
  move_noise_deg_ = options_.sigma_deg * util::GaussianFor(options_.seed, target_tenths);
  if (delta_deg == 0) {
    move_.reset();
    return;
  }
  move_ = std::make_unique<Move>(Move{position_deg_, position_deg_ + delta_deg, now_s});
}

std::string Lt360Emulator::Handle(const std::string& line, double now_s) {
  ++commands_served_;
  Advance(now_s);
  const std::optional<turntable::ParsedCommand> command =
      turntable::MatchCommand(options_.table, line);
  if (!command) return options_.table.error_reply;
  const int current = QuantiseTenths(position_deg_);
  const double value = command->value.value_or(0);
  // Targets are whole tenths: the table resolves 0.1 deg.
  const int target = ((static_cast<int>(std::lround(value * 10)) % 3600) + 3600) % 3600;
  const std::string& done = options_.table.done_reply;
  switch (command->kind) {
    case CommandKind::kGetPosition:
      return turntable::FormatPositionTenths(current);
    case CommandKind::kGetMoving:
      if (!move_) return "NO";
      return move_->to_deg > move_->from_deg ? "CCW" : "CW";
    case CommandKind::kGotoShortest:
    case CommandKind::kHome: {
      const int goal = command->kind == CommandKind::kHome ? 0 : target;
      int delta = ((goal - current) % 3600 + 3600) % 3600;
      if (delta > 1800) delta -= 3600;
      position_deg_ = std::round(position_deg_ * 10) / 10;  // moves start on a whole tenth
      StartMove(delta / 10.0, now_s);
      return done;
    }
    case CommandKind::kGotoCcw:
    case CommandKind::kGotoCw: {
      int delta = ((target - current) % 3600 + 3600) % 3600;  // CCW travel
      if (command->kind == CommandKind::kGotoCw && delta != 0) delta -= 3600;
      position_deg_ = std::round(position_deg_ * 10) / 10;  // moves start on a whole tenth
      StartMove(delta / 10.0, now_s);
      return done;
    }
    case CommandKind::kStep:
      StartMove(std::round(value * 10) / 10, now_s);
      return done;
    case CommandKind::kStop:
      move_.reset();
      return done;
    case CommandKind::kSetSpeed:
      if (!(value > 0)) return options_.table.error_reply;
      speed_deg_s_ = value;
      return done;
  }
  return options_.table.error_reply;
}

void Lt360Emulator::Reply(std::string reply) {
  if (reply.empty() || master_fd_ < 0) return;  // a table that answers actions with nothing
  bool terminate = true;
  if (fault_replies_ > 0) {
    --fault_replies_;
    switch (fault_) {
      case Lt360Fault::kNoReply:
        return;
      case Lt360Fault::kDropTerminator:
        terminate = false;
        break;
      case Lt360Fault::kGarbledReply:
        reply = "#~" + reply.substr(0, 1) + "\x7f?";
        break;
      default:
        break;
    }
  }
  if (terminate) reply += '\r';
  size_t written = 0;
  while (written < reply.size()) {
    const ssize_t n = ::write(master_fd_, reply.data() + written, reply.size() - written);
    if (n > 0) {
      written += static_cast<size_t>(n);
    } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
      return;  // nobody listening
    }
  }
}

void Lt360Emulator::Serve() {
  turntable::FrameSplitter splitter;
  while (true) {
    int master;
    {
      std::lock_guard lock(mutex_);
      master = master_fd_;
    }
    pollfd fds[2] = {{stop_fd_, POLLIN, 0}, {master, POLLIN, 0}};
    // A closed pty (Disconnect) leaves only the stop fd to wait on.
    const int ready = ::poll(fds, master >= 0 ? 2 : 1, 100);
    if (ready < 0 && errno != EINTR) return;
    if (fds[0].revents & POLLIN) return;
    if (master < 0 || !(fds[1].revents & POLLIN)) continue;
    char buffer[256];
    ssize_t n = 0;
    {
      // Under the lock so Disconnect() cannot close the fd between poll and read.
      std::lock_guard lock(mutex_);
      if (master_fd_ == master) n = ::read(master, buffer, sizeof(buffer));
    }
    if (n <= 0) continue;
    splitter.Feed(std::string_view(buffer, static_cast<size_t>(n)));
    while (std::optional<std::string> line = splitter.Next()) {
      if (line->empty()) continue;
      const double now = clock_->NowSeconds();
      std::lock_guard lock(mutex_);
      Reply(Handle(*line, now));
    }
  }
}

}  // namespace avc::sim
