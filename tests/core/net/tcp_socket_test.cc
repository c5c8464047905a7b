// The robot link's sockets are close-on-exec: a process that starts children must not leave its
// listening port held by them once it closes it. Our launcher (launch::ChildProcess) also marks
// every inherited descriptor close-on-exec, so the child here is started the plain way a library
// (posix_spawn, system, popen) would, which only the socket's own flag protects against.

#include "core/net/tcp_socket.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <memory>

namespace avc::net {
namespace {

TEST(TcpListener, APortClosedByItsOwnerIsFreeEvenWhileAChildStartedMeanwhileRuns) {
  auto listener = std::make_unique<TcpListener>("127.0.0.1", 0);
  const uint16_t port = listener->port();
  char sleep_name[] = "sleep";
  char duration[] = "30";
  char* argv[] = {sleep_name, duration, nullptr};
  pid_t child = 0;
  ASSERT_EQ(posix_spawnp(&child, "sleep", nullptr, nullptr, argv, environ), 0);
  listener.reset();
  // An inherited descriptor would keep the port listening in the child: "Address already in use".
  EXPECT_NO_THROW(TcpListener("127.0.0.1", port));
  // And the child does not answer on it.
  EXPECT_THROW(TcpStream::Connect("127.0.0.1", port, Milliseconds(500)), ConnectionError);
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
}

}  // namespace
}  // namespace avc::net
