// The client side of a TCP link (link/tcp_client.h), against link::TcpListener on loopback:
// the two read timeouts, a peer that closes (no SIGPIPE, the link reports itself closed),
// and connect errors that give the system's reason.
#include <gtest/gtest.h>
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <stdexcept>
#include <string>
#include <vector>

#include "amigobot_tracking/link/emulator_link.h"
#include "amigobot_tracking/link/tcp_client.h"

using amigobot_tracking::link::TcpAddress;
using amigobot_tracking::link::TcpClient;
using amigobot_tracking::link::TcpListener;

namespace {

// Connects `client` to `listener`: the server's end of the connection, or -1.
int connectPair(const TcpListener& listener, TcpClient* client) {
  client->connect(TcpAddress{"127.0.0.1", listener.port()}, 2000);
  pollfd p{listener.fd(), POLLIN, 0};
  if (::poll(&p, 1, 1000) <= 0) return -1;
  return listener.accept();
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST(LinkTcpClient, ReadsWhatArrivesAndWaitsNoLongerThanItsFirstTimeout) {
  TcpListener listener;
  listener.open("127.0.0.1", 0);
  TcpClient client;
  const int peer = connectPair(listener, &client);
  ASSERT_GE(peer, 0);
  char buffer[64];
  auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(client.read(buffer, sizeof(buffer), 100, 1), 0u);  // nothing sent: the first timeout
  EXPECT_GE(secondsSince(start), 0.09);
  EXPECT_TRUE(client.isOpen());
  ASSERT_EQ(::write(peer, "hello", 5), 5);
  EXPECT_EQ(client.write("ping", 4, 1000), 4u);
  start = std::chrono::steady_clock::now();
  ASSERT_EQ(client.read(buffer, sizeof(buffer), 1000, 20), 5u);  // the rest after 20 ms of silence
  EXPECT_LT(secondsSince(start), 0.9);
  EXPECT_EQ(std::string(buffer, 5), "hello");
  char got[4];
  ASSERT_EQ(::read(peer, got, 4), 4);
  EXPECT_EQ(std::string(got, 4), "ping");
  ::close(peer);
}

// The robot's transport ignored SIGPIPE for the whole process to survive this; the link now
// sends without it, so the default action (which would end this test binary) stays.
TEST(LinkTcpClient, APeerThatClosesIsAClosedLinkNotASignal) {
  ASSERT_EQ(std::signal(SIGPIPE, SIG_DFL), SIG_DFL) << "something set SIGPIPE's handler before the test";
  TcpListener listener;
  listener.open("127.0.0.1", 0);
  TcpClient client;
  const int peer = connectPair(listener, &client);
  ASSERT_GE(peer, 0);
  ::close(peer);
  char buffer[16];
  EXPECT_EQ(client.read(buffer, sizeof(buffer), 1000, 1), 0u);
  EXPECT_FALSE(client.isOpen());
  // A second client writes into a socket whose peer is gone: EPIPE, reported as a short write.
  TcpClient writer;
  const int peer2 = connectPair(listener, &writer);
  ASSERT_GE(peer2, 0);
  ::close(peer2);
  const std::vector<char> block(64 * 1024, 'x');
  std::size_t sent = block.size();
  for (int i = 0; i < 50 && sent == block.size(); ++i) sent = writer.write(block.data(), block.size(), 200);
  EXPECT_LT(sent, block.size());
  EXPECT_FALSE(writer.isOpen());
}

TEST(LinkTcpClient, ConnectErrorsGiveTheReason) {
  int free_port = 0;
  {
    TcpListener probe;
    probe.open("127.0.0.1", 0);
    free_port = probe.port();
  }
  TcpClient client;
  try {
    client.connect(TcpAddress{"127.0.0.1", free_port}, 1000);
    FAIL() << "connected to a port nobody serves";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "Connection refused");
  }
  EXPECT_FALSE(client.isOpen());
  try {
    client.connect(TcpAddress{"no-such-host.invalid", 80}, 1000);
    FAIL() << "resolved a .invalid name";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot resolve no-such-host.invalid"), std::string::npos) << e.what();
  }
}
