// The robot link's sockets are close-on-exec: a process that starts children (a cell's launcher,
// a test harness) must not leave its listening port held by them once it closes it.

#include "drivers/robot/tcp_socket.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/launch/child_process.h"

namespace avc::robot {
namespace {

TEST(TcpListener, APortClosedByItsOwnerIsFreeEvenWhileAChildStartedMeanwhileRuns) {
  auto listener = std::make_unique<TcpListener>("127.0.0.1", 0);
  const uint16_t port = listener->port();
  launch::SpawnSpec spec;
  spec.argv = {"sleep", "30"};
  launch::ChildProcess child = launch::ChildProcess::Spawn(spec);
  listener.reset();
  // An inherited descriptor would keep the port listening in the child: "Address already in use".
  EXPECT_NO_THROW(TcpListener("127.0.0.1", port));
  // And the child does not answer on it.
  EXPECT_THROW(TcpStream::Connect("127.0.0.1", port, Milliseconds(500)), ConnectionError);
}

}  // namespace
}  // namespace avc::robot
