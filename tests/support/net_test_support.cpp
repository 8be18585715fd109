#include "tests/support/net_test_support.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "octopoint/models.h"
#include "tests/support/model_images.h"

namespace octopoint::testing {
namespace {

using Clock = std::chrono::steady_clock;

int connectTo(int port) {
  const int sock = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(sock, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    ::close(sock);
    throw std::runtime_error("cannot connect to 127.0.0.1:" + std::to_string(port));
  }
  return sock;
}

// Reads what is there within `timeout`; false when the peer closed.
bool readFor(int sock, std::string& into, Clock::time_point deadline) {
  char buffer[4096];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return true;
    pollfd entry{sock, POLLIN, 0};
    if (::poll(&entry, 1, static_cast<int>(left)) <= 0) return true;
    const ssize_t got = ::recv(sock, buffer, sizeof buffer, 0);
    if (got <= 0) return false;
    into.append(buffer, static_cast<std::size_t>(got));
  }
}

// Reads once (whatever one recv gives) within the deadline; false when the peer closed or nothing
// came.
bool readSome(int sock, std::string& into, Clock::time_point deadline) {
  const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  pollfd entry{sock, POLLIN, 0};
  if (left <= 0 || ::poll(&entry, 1, static_cast<int>(left)) <= 0) return true;
  char buffer[4096];
  const ssize_t got = ::recv(sock, buffer, sizeof buffer, 0);
  if (got <= 0) return false;
  into.append(buffer, static_cast<std::size_t>(got));
  return true;
}

}  // namespace

const std::vector<std::uint8_t>& streamedModelImage() {
  static const std::vector<std::uint8_t> image =
      fuzzing::chunkedImage(*models::defaultModel(), {5, 6, 7, 8}, {1024, 1500});
  return image;
}

TempFolder::TempFolder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "octopoint-net-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempFolder::~TempFolder() {
  std::error_code error;
  std::filesystem::remove_all(path_, error);
}

void TempFolder::write(const std::string& name, const std::vector<std::uint8_t>& bytes) const {
  std::ofstream out(path_ / name, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

RunningServer::RunningServer(net::ServerOptions options)
    : server_(std::make_unique<net::ModelServer>(std::move(options))) {
  std::string error;
  if (!server_->bind(&error)) throw std::runtime_error(error);
  port_ = server_->port();
  thread_ = std::thread([this] { server_->run(); });
}

RunningServer::~RunningServer() { stop(); }

void RunningServer::stop() {
  if (!thread_.joinable()) return;
  server_->stop();
  thread_.join();
}

int Exchange::status() const {
  int code = 0;
  return std::sscanf(response.c_str(), "HTTP/1.%*d %d", &code) == 1 ? code : 0;
}

Exchange rawExchange(int port, const std::string& request, std::chrono::milliseconds timeout,
                     std::size_t piece, std::chrono::milliseconds pause) {
  const int sock = connectTo(port);
  const auto deadline = Clock::now() + timeout;
  Exchange exchange;
  const std::size_t step = piece == 0 ? request.size() : piece;
  bool open = true;
  for (std::size_t at = 0; at < request.size() && open; at += step) {
    const std::string part = request.substr(at, step);
    if (::send(sock, part.data(), part.size(), MSG_NOSIGNAL) < 0) break;
    if (pause.count() > 0)
      open = readFor(sock, exchange.response, std::min(deadline, Clock::now() + pause));
    if (Clock::now() >= deadline) break;
  }
  if (open) open = readFor(sock, exchange.response, deadline);
  exchange.closed_by_server = !open;
  ::close(sock);
  return exchange;
}

IdleConnection::IdleConnection(int port) : socket_(connectTo(port)) {}
IdleConnection::~IdleConnection() { ::close(socket_); }

void IdleConnection::send(const std::string& bytes) {
  ::send(socket_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
}

std::string IdleConnection::read(std::chrono::milliseconds timeout) {
  std::string got;
  readFor(socket_, got, Clock::now() + timeout);
  return got;
}

int listenOnLoopback(int port, int* bound_port, const char* who) {
  const int listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int yes = 1;
  ::setsockopt(listener, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listener, 16) != 0) {
    ::close(listener);
    throw std::runtime_error(std::string(who) + ": cannot listen");
  }
  socklen_t length = sizeof address;
  ::getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length);
  *bound_port = ntohs(address.sin_port);
  return listener;
}

ScriptedServer::ScriptedServer(Respond respond, int port) : respond_(std::move(respond)) {
  listener_ = listenOnLoopback(port, &port_, "scripted server");
  thread_ = std::thread([this] { serve(); });
}

ScriptedServer::~ScriptedServer() {
  stopping_ = true;
  ::shutdown(listener_, SHUT_RDWR);
  thread_.join();
  ::close(listener_);
}

void ScriptedServer::sendAll(int socket, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(socket, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return;
    sent += static_cast<std::size_t>(n);
  }
}

std::string ScriptedServer::partialHeader(std::uint64_t first, std::uint64_t last,
                                          std::uint64_t total, std::uint64_t content_length) {
  return "HTTP/1.1 206 Partial Content\r\nContent-Range: bytes " + std::to_string(first) + "-" +
         std::to_string(last) + "/" + std::to_string(total) +
         "\r\nContent-Length: " + std::to_string(content_length) + "\r\n\r\n";
}

void ScriptedServer::serve() {
  std::vector<std::thread> connections;
  while (!stopping_) {
    pollfd entry{listener_, POLLIN, 0};
    if (::poll(&entry, 1, 100) <= 0) continue;
    const int sock = ::accept(listener_, nullptr, nullptr);
    if (sock >= 0) connections.emplace_back([this, sock] { converse(sock); });
  }
  for (std::thread& connection : connections) connection.join();
}

void ScriptedServer::converse(int sock) {
  std::string pending;
  bool keep = true;
  while (keep && !stopping_) {
    // One request: up to the blank line.
    std::size_t end = std::string::npos;
    while (keep && (end = pending.find("\r\n\r\n")) == std::string::npos) {
      keep = readSome(sock, pending, Clock::now() + std::chrono::milliseconds(200)) && !stopping_ &&
             pending.size() <= 65536;
    }
    if (!keep) break;
    const std::string head = pending.substr(0, end);
    pending.erase(0, end + 4);
    ++requests_;
    unsigned long long first = 0, last = UINT64_MAX;
    const std::size_t range = head.find("Range: bytes=");
    if (range != std::string::npos)
      std::sscanf(head.c_str() + range, "Range: bytes=%llu-%llu", &first, &last);
    keep = respond_(first, last, sock);
  }
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
}

}  // namespace octopoint::testing
