#pragma once
// One TCP connection of the HTTP client, over POSIX sockets: connecting within a time limit
// (a non-blocking connect, then poll), reads and writes that wait at most until a deadline, and an
// abort that another thread can call to end any wait at once. Errors come back in words
// ("connection refused", "connection reset by peer"), never as a bare code.

#include <chrono>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace octopoint::net {

class HttpConnection {
 public:
  using Clock = std::chrono::steady_clock;

  HttpConnection();
  ~HttpConnection();
  HttpConnection(const HttpConnection&) = delete;
  HttpConnection& operator=(const HttpConnection&) = delete;

  // Resolves `host` (net/name_lookup.h) and connects to `port` before `deadline`, the lookup
  // included; "" when connected, else why.
  [[nodiscard]] std::string connect(const std::string& host, int port, Clock::time_point deadline);
  bool connected() const { return socket_ >= 0; }
  void close();

  enum class Outcome { kDone, kClosed, kTimeout, kError, kAborted };
  struct Io {
    Outcome outcome = Outcome::kDone;
    std::size_t bytes = 0;  // received (receive)
    std::string error;      // kError: the reason in words
  };
  // Sends all of `bytes`, or fails, by `deadline`.
  [[nodiscard]] Io send(std::string_view bytes, Clock::time_point deadline);
  // Receives what is there (at least one byte, at most buffer.size()), waiting until `deadline`.
  // kClosed: the server closed the connection (no byte).
  [[nodiscard]] Io receive(std::span<char> buffer, Clock::time_point deadline);

  // From any thread: ends the wait of a connect, send or receive at once (kAborted), and every
  // later one until clearAbort().
  void abort();
  void clearAbort();

 private:
  // Waits for `events` on the socket; kDone when they came.
  Outcome wait(short events, Clock::time_point deadline);

  int socket_ = -1;
  int wake_ = -1;  // an eventfd: readable once aborted
};

}  // namespace octopoint::net
