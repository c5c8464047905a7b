#pragma once

// The emulated controller's RTDE interface (30004), one session per client: protocol 2 and 1,
// the CB3 version, output recipes checked against the variable table with real type strings
// (NOT_FOUND for unknown names, frequency in (0, control rate]), input recipes (IN_USE when
// another client owns a register), start/pause, and data packages at the requested rate that are
// dropped, never queued without bound, when the client is slow.

#include <map>
#include <string>
#include <vector>

#include "drivers/robot/protocol/rtde_protocol.h"
#include "sim/emulators/ur5/ur5_controller.h"
#include "sim/emulators/ur5/ur5_session.h"

namespace avc::sim::ur5 {

// Which session owns each input variable (shared by every RTDE session of one controller).
using RtdeInputOwners = std::map<std::string, int>;

class RtdeSession final : public Session {
 public:
  RtdeSession(int id, net::TcpStream stream, Ur5Controller& controller, RtdeInputOwners& owners);
  // Releases the inputs this session owned.
  ~RtdeSession() override;

  // Sends a data package when the recipe's period has passed.
  void OnTick() override;
  bool streaming() const { return started_; }

 private:
  struct InputRecipe {
    std::vector<std::string> names;
    std::vector<robot::rtde::ValueType> types;
  };

  void Consume(const uint8_t* data, size_t size) override;
  void OnMalformed(const std::string& what) override;
  void Handle(const robot::rtde::Packet& packet);
  void SetupOutputs(const robot::rtde::SetupOutputsRequest& request);
  void SetupInputs(const std::vector<std::string>& names);
  void WriteInputs(const std::vector<uint8_t>& payload);
  void Reply(robot::rtde::PacketType type, const std::vector<uint8_t>& payload);
  void Text(const std::string& text, robot::rtde::MessageLevel level);

  Ur5Controller& controller_;
  RtdeInputOwners& owners_;
  robot::rtde::PacketFramer framer_;
  int protocol_ = 1;
  std::vector<std::string> output_names_;
  std::vector<robot::rtde::ValueType> output_types_;
  double period_ = 0;  // simulated seconds between data packages
  double since_last_ = 0;
  bool started_ = false;
  std::map<uint8_t, InputRecipe> inputs_;
  uint8_t next_input_id_ = 1;
};

}  // namespace avc::sim::ur5
