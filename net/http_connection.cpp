#include "net/http_connection.h"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "net/name_lookup.h"

namespace octopoint::net {
namespace {

// strerror, starting in lower case, to sit inside a sentence.
std::string reason(int error) {
  std::string text = std::strerror(error);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

int millisecondsUntil(HttpConnection::Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
      deadline - HttpConnection::Clock::now());
  return static_cast<int>(std::clamp<std::chrono::milliseconds::rep>(left.count(), 0, 3'600'000));
}

std::string hostPort(const std::string& host, int port) {
  return (host.find(':') != std::string::npos ? "[" + host + "]" : host) + ":" +
         std::to_string(port);
}

}  // namespace

HttpConnection::HttpConnection() : wake_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
  if (wake_ < 0) throw std::runtime_error("eventfd: " + reason(errno));
}

HttpConnection::~HttpConnection() {
  close();
  ::close(wake_);
}

void HttpConnection::close() {
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
}

void HttpConnection::abort() {
  const std::uint64_t one = 1;
  static_cast<void>(::write(wake_, &one, sizeof one));
}

void HttpConnection::clearAbort() {
  std::uint64_t count = 0;
  static_cast<void>(::read(wake_, &count, sizeof count));
}

HttpConnection::Outcome HttpConnection::wait(short events, Clock::time_point deadline) {
  for (;;) {
    pollfd entries[2] = {{socket_, events, 0}, {wake_, POLLIN, 0}};
    const int ready = ::poll(entries, 2, millisecondsUntil(deadline));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return Outcome::kError;
    if (entries[1].revents != 0) return Outcome::kAborted;
    if (ready == 0) return Outcome::kTimeout;
    return Outcome::kDone;  // readable, writable, or an error that the next call reports
  }
}

std::string HttpConnection::connect(const std::string& host, int port, Clock::time_point deadline) {
  close();
  Addresses found;
  if (std::string why = lookUp(host, port, deadline, wake_, found); !why.empty()) return why;
  std::string why = "no address for " + host;
  for (addrinfo* at = found.get(); at != nullptr; at = at->ai_next) {
    socket_ =
        ::socket(at->ai_family, at->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, at->ai_protocol);
    if (socket_ < 0) {
      why = "cannot make a socket: " + reason(errno);
      continue;
    }
    const int yes = 1;  // a request goes out whole at once, never behind an ACK
    ::setsockopt(socket_, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    int error = 0;
    if (::connect(socket_, at->ai_addr, at->ai_addrlen) != 0) {
      error = errno;
      if (error == EINPROGRESS) {
        const Outcome outcome = wait(POLLOUT, deadline);
        if (outcome == Outcome::kAborted) {
          why = "aborted";
          close();
          break;
        }
        socklen_t length = sizeof error;
        if (outcome == Outcome::kTimeout)
          error = ETIMEDOUT;
        else
          ::getsockopt(socket_, SOL_SOCKET, SO_ERROR, &error, &length);
      }
    }
    if (error == 0) break;
    why = "cannot connect to " + hostPort(host, port) + ": " +
          (error == ETIMEDOUT ? "no answer in time" : reason(error));
    close();
  }
  return socket_ >= 0 ? std::string() : why;
}

HttpConnection::Io HttpConnection::send(std::string_view bytes, Clock::time_point deadline) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(socket_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      const Outcome outcome = wait(POLLOUT, deadline);
      if (outcome != Outcome::kDone) return {outcome, 0, "cannot send the request in time"};
      continue;
    }
    return {Outcome::kError, 0, "cannot send the request: " + reason(errno)};
  }
  return {Outcome::kDone, 0, {}};
}

HttpConnection::Io HttpConnection::receive(std::span<char> buffer, Clock::time_point deadline) {
  for (;;) {
    const ssize_t n = ::recv(socket_, buffer.data(), buffer.size(), 0);
    if (n > 0) return {Outcome::kDone, static_cast<std::size_t>(n), {}};
    if (n == 0) return {Outcome::kClosed, 0, {}};
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) return {Outcome::kError, 0, reason(errno)};
    const Outcome outcome = wait(POLLIN, deadline);
    if (outcome != Outcome::kDone) return {outcome, 0, {}};
  }
}

}  // namespace octopoint::net
