// The line framing the robot emulator's status and control sockets share (link/emulator_link.h):
// takeLine, and LineClients over socket pairs: lines in order, an unfinished line kept for its
// rest, and the three ways a client ends (it hangs up, its handler refuses, no line break).
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "amigobot_tracking/link/emulator_link.h"

using amigobot_tracking::link::LineClients;
using amigobot_tracking::link::takeLine;

namespace {

// A connected pair of stream sockets: [0] the client's end, [1] the server's (handed to LineClients).
std::vector<int> socketPair() {
  int fds[2] = {-1, -1};
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) return {};
  return {fds[0], fds[1]};
}

void sendText(int fd, const std::string& text) { ASSERT_EQ(::write(fd, text.data(), text.size()), static_cast<ssize_t>(text.size())); }

}  // namespace

TEST(LinkTakeLine, TakesCompleteLinesInOrderAndLeavesTheRest) {
  std::string pending = "one\n\ntwo\nthr";
  std::string line;
  ASSERT_TRUE(takeLine(pending, &line));
  EXPECT_EQ(line, "one");
  ASSERT_TRUE(takeLine(pending, &line));
  EXPECT_EQ(line, "");
  ASSERT_TRUE(takeLine(pending, &line));
  EXPECT_EQ(line, "two");
  line = "unchanged";
  EXPECT_FALSE(takeLine(pending, &line));
  EXPECT_EQ(line, "unchanged");
  EXPECT_EQ(pending, "thr");
}

TEST(LinkLineClients, ServesEachLineInOrderAndKeepsAnUnfinishedLineForItsRest) {
  const std::vector<int> pair = socketPair();
  ASSERT_EQ(pair.size(), 2u);
  LineClients clients;
  clients.add(pair[1]);
  std::vector<std::string> heard;
  const auto serve = [&](int fd, const std::string& line) {
    EXPECT_EQ(fd, pair[1]);
    heard.push_back(line);
    return true;
  };
  sendText(pair[0], "a 1\nb 2\nc");
  clients.read(0, serve);
  EXPECT_EQ(heard, (std::vector<std::string>{"a 1", "b 2"}));
  sendText(pair[0], " 3\n");
  clients.read(0, serve);
  EXPECT_EQ(heard, (std::vector<std::string>{"a 1", "b 2", "c 3"}));
  clients.sweep();
  EXPECT_EQ(clients.size(), 1u);
  ::close(pair[0]);
}

TEST(LinkLineClients, EndsAClientThatHangsUpIsRefusedOrSendsNoLineBreak) {
  std::vector<std::vector<int>> pairs;
  LineClients clients;
  for (int k = 0; k < 4; ++k) {
    pairs.push_back(socketPair());
    ASSERT_EQ(pairs.back().size(), 2u);
    clients.add(pairs.back()[1]);
  }
  ::close(pairs[0][0]);                    // hangs up
  sendText(pairs[1][0], "refused\n");          // its handler says no
  sendText(pairs[2][0], std::string(9, 'x'));  // 9 bytes without a line break, over the bound of 8
  sendText(pairs[3][0], "fine\n");
  const auto serve = [](int, const std::string& line) { return line != "refused"; };
  for (std::size_t k = 0; k < clients.size(); ++k) clients.read(k, serve, 8);
  EXPECT_EQ(clients.fd(0), -1);  // closed at once, removed by sweep()
  clients.sweep();
  ASSERT_EQ(clients.size(), 1u);
  EXPECT_EQ(clients.fd(0), pairs[3][1]);
  char byte;
  EXPECT_EQ(::read(pairs[1][0], &byte, 1), 0);  // the server's end is closed: end of file
  for (int k = 1; k < 4; ++k) ::close(pairs[static_cast<std::size_t>(k)][0]);
}
