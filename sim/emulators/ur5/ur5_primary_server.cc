#include "sim/emulators/ur5/ur5_primary_server.h"

#include <string>

#include "drivers/robot/protocol/primary_protocol.h"
#include "drivers/robot/protocol/primary_robot_state.h"

namespace avc::sim::ur5 {

PrimarySession::PrimarySession(int id, net::TcpStream stream, Ur5Controller& controller)
    : Session(id, std::move(stream)), controller_(controller) {
  Queue(robot::primary::EncodeVersionMessage(controller_.Version(),
                                             static_cast<uint64_t>(controller_.time() * 1e6)));
  QueueState();
}

void PrimarySession::QueueState() {
  // A slow reader misses states rather than growing the queue.
  if (queued() < kMaxQueuedBytes) {
    Queue(robot::primary::EncodeRobotState(controller_.PrimaryState()));
  }
}

void PrimarySession::OnTick() {
  since_state_ += controller_.dt();
  if (since_state_ + 1e-9 < kRobotStatePeriod) return;
  since_state_ = 0;
  QueueState();
}

void PrimarySession::Consume(const uint8_t* data, size_t size) {
  assembler_.Append(std::string(reinterpret_cast<const char*>(data), size));
  while (auto unit = assembler_.Next()) controller_.RunScript(id(), *unit);
}

}  // namespace avc::sim::ur5
