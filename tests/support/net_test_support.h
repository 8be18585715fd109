#pragma once
// Real servers for the transport tests, all on 127.0.0.1 and a free port: octopoint's own
// (ModelServer, in this process), and a misbehaving one whose every response a test scripts, to
// see what the client does when a server lies, stalls, cuts off or never stops talking. Plus a raw
// socket exchange, to send a server what no well-behaved client would.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "net/model_server.h"

namespace octopoint::testing {

// A socket listening on 127.0.0.1:`port` (0: a free port, which `*bound_port` receives). Throws
// std::runtime_error "WHO: cannot listen" when it cannot bind or listen.
int listenOnLoopback(int port, int* bound_port, const char* who);

// The default model as a chunked file (depths 5 to 8, chunks of 1024 and 1500 bytes): what the
// transport's tests serve, made once.
const std::vector<std::uint8_t>& streamedModelImage();

// A fresh folder under the system's temporary directory, removed with everything in it.
class TempFolder {
 public:
  TempFolder();
  ~TempFolder();
  const std::filesystem::path& path() const { return path_; }
  void write(const std::string& name, const std::vector<std::uint8_t>& bytes) const;

 private:
  std::filesystem::path path_;
};

// A ModelServer running on its own thread until destroyed (or stop()).
class RunningServer {
 public:
  explicit RunningServer(net::ServerOptions options);
  ~RunningServer();
  int port() const { return port_; }
  void stop();
  net::ModelServer& server() { return *server_; }

 private:
  std::unique_ptr<net::ModelServer> server_;
  std::thread thread_;
  int port_ = 0;
};

// Sends `request` on a new connection (in pieces of `piece` bytes, `pause` apart, when given) and
// reads until the server closes it or `timeout` passes. Returns what came back ("" when nothing).
struct Exchange {
  std::string response;
  bool closed_by_server = false;  // the connection ended before the timeout
  int status() const;             // the status code, or 0
};
Exchange rawExchange(int port, const std::string& request, std::chrono::milliseconds timeout,
                     std::size_t piece = 0, std::chrono::milliseconds pause = {});

// A TCP connection that stays open, doing nothing, until destroyed.
class IdleConnection {
 public:
  explicit IdleConnection(int port);
  ~IdleConnection();
  void send(const std::string& bytes);
  // What the server sent within `timeout` ("" when nothing).
  std::string read(std::chrono::milliseconds timeout);

 private:
  int socket_ = -1;
};

// A server whose response to each request a test writes: `respond(first, last, socket)` gets the
// requested byte range (inclusive; the whole file when no Range came) and writes whatever it likes
// to the socket; returning false closes the connection. Each connection has its own thread, so
// `respond` must be thread-safe.
class ScriptedServer {
 public:
  using Respond = std::function<bool(std::uint64_t first, std::uint64_t last, int socket)>;
  explicit ScriptedServer(Respond respond, int port = 0);
  ~ScriptedServer();
  int port() const { return port_; }
  int requests() const { return requests_.load(); }

  // Helpers for scripts: a correct 206 response for [first, last] of `file`, and a header block.
  static void sendAll(int socket, const std::string& bytes);
  static std::string partialHeader(std::uint64_t first, std::uint64_t last, std::uint64_t total,
                                   std::uint64_t content_length);

 private:
  void serve();
  void converse(int sock);

  Respond respond_;
  int listener_ = -1;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::atomic<int> requests_{0};
  std::thread thread_;
};

}  // namespace octopoint::testing
