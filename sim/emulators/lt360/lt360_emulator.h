#pragma once

// An LT360 turntable behind a pseudo-terminal: the driver opens device_path() exactly like
// /dev/ttyUSB0, so the real serial backend is what runs against it.
// It speaks the grammar of a CommandTable (case-insensitive, CR or NUL terminated, waits
// silently for a terminator), moves at a set speed, reports the angle quantised to 0.1 deg
// while the true angle carries a seeded error model, and injects faults on request.
//
// Angles increase counter-clockwise seen from above (math-positive about the table's z axis):
// "CW" motion decreases the reported angle, a positive step turns CCW.

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "drivers/turntable/protocol/lt360_protocol.h"
#include "sim/emulators/clock/emulator_clock.h"

namespace avc::sim {

struct Lt360EmulatorOptions {
  turntable::CommandTable table;
  double speed_deg_s = 30;  // until a speed command changes it
  double accel_deg_s2 = 0;  // 0 = full speed at once; stop is always immediate
  double start_deg = 0;
  // True angle = reported * (1 + scale_error) + offset_deg + e, with e ~ N(0, sigma_deg) a
  // repeatable error of each target position (keyed by seed and target tenth).
  double offset_deg = 0;
  double scale_error = 0;
  double sigma_deg = 0;
  uint64_t seed = 1;

  std::string Validate() const;
};

// Degrees covered t seconds into a move of `distance` with a trapezoidal speed profile (accel 0 =
// constant speed); never more than distance.
double TravelledDeg(double distance, double speed, double accel, double t);

enum class Lt360Fault {
  kNone,
  kDropTerminator,  // the reply is sent without its CR
  kGarbledReply,    // the reply is replaced by garbage
  kNoReply,         // the command is executed but nothing is answered
  kStall,           // the table stops turning but keeps reporting motion (until ClearFaults)
};

class Lt360Emulator {
 public:
  // Opens the pty and starts serving on a background thread. Throws std::runtime_error when no
  // pty can be opened, std::invalid_argument for bad options. clock defaults to real time.
  explicit Lt360Emulator(Lt360EmulatorOptions options,
                         std::shared_ptr<EmulatorClock> clock = nullptr);
  ~Lt360Emulator();
  Lt360Emulator(const Lt360Emulator&) = delete;
  Lt360Emulator& operator=(const Lt360Emulator&) = delete;

  // The slave side, e.g. "/dev/pts/3".
  const std::string& device_path() const { return device_path_; }

  // The next `replies` replies get the fault (kStall ignores the count and lasts until cleared).
  void InjectFault(Lt360Fault fault, int replies = 1);
  void ClearFaults();
  // Closes the pty as an unplugged adapter would; the driver sees a hang-up.
  void Disconnect();

  // State as of the last command served (reading it does not advance a stepped clock).
  int ReportedTenths() const;
  double TrueAngleDeg() const;
  bool moving() const;
  double speed_deg_s() const;
  int64_t commands_served() const;
  int64_t moves_started() const;

 private:
  struct Move {
    double from_deg;
    double to_deg;  // unwrapped: to - from is the signed travel
    double start_s;
  };

  void Serve();
  std::string Handle(const std::string& line, double now_s);  // under mutex_
  void Advance(double now_s);                                 // under mutex_
  void StartMove(double delta_deg, double now_s);             // under mutex_
  void Reply(std::string reply);                              // under mutex_

  Lt360EmulatorOptions options_;
  std::shared_ptr<EmulatorClock> clock_;
  std::string device_path_;
  int master_fd_ = -1;
  int slave_fd_ = -1;  // kept open so the pty survives the driver closing and reopening it
  int stop_fd_ = -1;   // eventfd that ends Serve()

  mutable std::mutex mutex_;
  double position_deg_ = 0;  // unwrapped, exact (reported is this rounded to 0.1 deg)
  double move_noise_deg_ = 0;
  double speed_deg_s_;
  std::unique_ptr<Move> move_;
  bool stalled_ = false;
  Lt360Fault fault_ = Lt360Fault::kNone;
  int fault_replies_ = 0;
  int64_t commands_served_ = 0;
  int64_t moves_started_ = 0;
  std::thread thread_;
};

}  // namespace avc::sim
