// The connect deadline bounds the name lookup too (net/name_lookup.h). A name server that never
// answers is made for real: a child process with a mount namespace of its own has
// /etc/resolv.conf point at 127.0.0.1, where a UDP socket of the child's takes each query and
// says nothing (the system resolver would then wait resolv.conf's 20 s timeout).

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include "net/http_connection.h"

namespace octopoint::net {
namespace {

using Clock = std::chrono::steady_clock;

// The child's checks; its exit status says which failed (0: all held), its stderr how.
int checkWithASilentNameServer() {
  if (::unshare(CLONE_NEWNS) != 0 || ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr))
    return std::perror("mount namespace"), 10;
  char conf[] = "/tmp/octopoint_resolv_XXXXXX";
  const int fd = ::mkstemp(conf);
  if (fd < 0) return std::perror("mkstemp"), 11;
  const std::string text = "nameserver 127.0.0.1\noptions timeout:20 attempts:1\n";
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  ::close(fd);
  const bool bound = written && ::mount(conf, "/etc/resolv.conf", nullptr, MS_BIND, nullptr) == 0;
  ::unlink(conf);  // the bind mount keeps the file
  if (!bound) return std::perror("bind mount over /etc/resolv.conf"), 12;
  const int server = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(53);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(server, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0)
    return std::perror("UDP 127.0.0.1:53"), 13;

  HttpConnection connection;
  auto start = Clock::now();
  std::string why =
      connection.connect("octopoint-silent.test", 80, start + std::chrono::seconds(1));
  double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  char query[512];
  if (::recv(server, query, sizeof query, MSG_DONTWAIT) <= 0) {
    std::fprintf(stderr, "the lookup asked no query of the silent server (%s)\n", why.c_str());
    return 14;
  }
  if (why != "cannot resolve octopoint-silent.test: no answer in time" || seconds > 2.0) {
    std::fprintf(stderr, "deadline 1 s: '%s' after %.2f s\n", why.c_str(), seconds);
    return 15;
  }
  // An abort from another thread ends the lookup at once, well before its 30 s deadline.
  start = Clock::now();
  std::thread aborter([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    connection.abort();
  });
  why = connection.connect("octopoint-silent-2.test", 80, start + std::chrono::seconds(30));
  seconds = std::chrono::duration<double>(Clock::now() - start).count();
  aborter.join();
  if (why != "aborted" || seconds > 1.0) {
    std::fprintf(stderr, "abort after 0.2 s: '%s' after %.2f s\n", why.c_str(), seconds);
    return 16;
  }
  return 0;
}

TEST(NameLookup, ASilentNameServerIsBoundedByTheConnectDeadlineAndAnAbort) {
  if (::geteuid() != 0)
    GTEST_SKIP() << "needs root: a mount namespace to point the resolver at a silent server";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(checkWithASilentNameServer());
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "see the child's line on stderr above";
}

TEST(NameLookup, ANumericAddressNeedsNoLookup) {
  HttpConnection connection;  // nothing listens on port 1: refused, not "cannot resolve"
  const std::string why =
      connection.connect("127.0.0.1", 1, Clock::now() + std::chrono::seconds(5));
  EXPECT_EQ(why, "cannot connect to 127.0.0.1:1: connection refused");
}

}  // namespace
}  // namespace octopoint::net
