#pragma once
// The HTTP server behind octopoint-serve: model files from one folder, with Range requests, each
// connection optionally shaped to a slow link (a rate and a latency), on Debian's cpp-httplib.
//
// What it refuses (tests/net): any path outside the folder (net/served_path.h: "..", absolute
// paths, percent-encoded forms, links pointing out); malformed, multiple or unsatisfiable ranges
// (416); a request whose line and headers exceed kMaxRequestBytes, or that has not arrived whole
// `request_seconds` after its first byte (the connection is closed); a client that takes no bytes
// for `write_timeout_seconds`; more than `max_connections` connections at once (503, closed at
// once).
// Each connection has its own thread from a fixed pool, so memory does not grow with load.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace octopoint::net {

struct ServerOptions {
  std::filesystem::path root;  // the folder served
  std::string bind_address = "127.0.0.1";
  int port = 8080;                          // 0: any free port (see ModelServer::port)
  std::uint64_t rate_bytes_per_second = 0;  // 0: unshaped
  std::uint32_t latency_ms = 0;  // added before each response, as a slow link's round trip
  int max_connections = 64;
  int request_seconds = 10;        // from a request's first byte to its end
  int keep_alive_seconds = 5;      // idle time between requests
  int write_timeout_seconds = 10;  // a client that takes no bytes for this long is cut off
};

inline constexpr std::size_t kMaxRequestBytes = 16 * 1024;  // request line and headers

class ModelServer {
 public:
  explicit ModelServer(ServerOptions options);
  ~ModelServer();
  ModelServer(const ModelServer&) = delete;
  ModelServer& operator=(const ModelServer&) = delete;

  // Binds; false with `error` set when the folder or the address cannot be used.
  bool bind(std::string* error);
  int port() const;
  // Serves until stop() (from another thread or a signal handler's thread).
  void run();
  void stop();

  // Counters, for tests and the log line at exit.
  std::uint64_t requestsServed() const;
  std::uint64_t connectionsRefused() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace octopoint::net
