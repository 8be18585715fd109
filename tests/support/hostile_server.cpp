#include "tests/support/hostile_server.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "tests/support/net_test_support.h"

namespace octopoint::testing {
namespace {

enum Verdict { kKeep, kClose, kReset };

std::string rangeHead(std::uint64_t first, std::uint64_t last, std::uint64_t total,
                      std::uint64_t length) {
  return "HTTP/1.1 206 Partial Content\r\nContent-Range: bytes " + std::to_string(first) + "-" +
         std::to_string(last) + "/" + std::to_string(total) +
         "\r\nContent-Length: " + std::to_string(length) + "\r\n\r\n";
}

std::string hex(std::size_t value) {
  char text[32];
  std::snprintf(text, sizeof text, "%zx", value);
  return text;
}

}  // namespace

HostileServer::HostileServer(std::vector<std::uint8_t> file, HostileOptions options)
    : file_(std::move(file)), options_(options) {
  listener_ = listenOnLoopback(0, &port_, "hostile server");
  thread_ = std::thread([this] { serve(); });
}

HostileServer::~HostileServer() {
  stopping_ = true;
  thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  for (std::thread& connection : connections_) connection.join();
  ::close(listener_);
}

std::string HostileServer::url() const {
  return "http://127.0.0.1:" + std::to_string(port_) + "/model.oct";
}

void HostileServer::serve() {
  while (!stopping_) {
    pollfd entry{listener_, POLLIN, 0};
    if (::poll(&entry, 1, 50) <= 0) continue;
    const int sock = ::accept4(listener_, nullptr, nullptr, SOCK_CLOEXEC);
    if (sock < 0) continue;
    std::lock_guard<std::mutex> lock(mutex_);
    connections_.emplace_back([this, sock] { converse(sock); });
  }
}

bool HostileServer::sendAll(int sock, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size() && !stopping_) {
    pollfd entry{sock, POLLOUT, 0};
    if (::poll(&entry, 1, 50) <= 0) continue;
    const ssize_t n =
        ::send(sock, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return sent == bytes.size();
}

// `prefix`, then `filler` for as long as the client reads (or the server stops).
bool HostileServer::sendEndless(int sock, const std::string& prefix, char filler) {
  if (!sendAll(sock, prefix)) return false;
  const std::string block(64 * 1024, filler);
  while (!stopping_ && sendAll(sock, block)) {
  }
  return false;
}

void HostileServer::converse(int sock) {
  std::string pending;
  char buffer[4096];
  int verdict = kKeep;
  while (verdict == kKeep && !stopping_) {
    const std::size_t end = pending.find("\r\n\r\n");
    if (end == std::string::npos) {
      pollfd entry{sock, POLLIN, 0};
      if (::poll(&entry, 1, 50) <= 0) continue;
      const ssize_t n = ::recv(sock, buffer, sizeof buffer, 0);
      if (n <= 0 || pending.size() > 65536) break;
      pending.append(buffer, static_cast<std::size_t>(n));
      continue;
    }
    const std::string head = pending.substr(0, end);
    pending.erase(0, end + 4);
    ++requests_;
    unsigned long long first = 0, last = file_.empty() ? 0 : file_.size() - 1;
    if (const std::size_t at = head.find("Range: bytes="); at != std::string::npos)
      std::sscanf(head.c_str() + at, "Range: bytes=%llu-%llu", &first, &last);
    verdict = answer(sock, first, last);
  }
  if (verdict == kReset) {
    const linger abrupt{1, 0};  // close sends RST, not FIN
    ::setsockopt(sock, SOL_SOCKET, SO_LINGER, &abrupt, sizeof abrupt);
  } else {
    ::shutdown(sock, SHUT_RDWR);
  }
  ::close(sock);
}

int HostileServer::answer(int sock, std::uint64_t first, std::uint64_t last) {
  if (first >= file_.size()) {
    sendAll(sock, "HTTP/1.1 416 Range Not Satisfiable\r\nContent-Length: 0\r\n\r\n");
    return kKeep;
  }
  last = std::min<std::uint64_t>(last, file_.size() - 1);
  std::string body(file_.begin() + static_cast<std::ptrdiff_t>(first),
                   file_.begin() + static_cast<std::ptrdiff_t>(last + 1));
  const std::string honest_head = rangeHead(first, last, file_.size(), body.size());
  if (options_.lie == Lie::kNone || first < options_.lie_from)
    return sendAll(sock, honest_head + body) ? kKeep : kClose;
  const int verdict = lieInHead(sock, honest_head, body);
  return verdict >= 0 ? verdict : lieAboutRange(sock, first, last, body);
}

// The lies about the status line and the header lines; -1 when the lie is another.
int HostileServer::lieInHead(int sock, const std::string& honest_head, const std::string& body) {
  const std::string status_line = "HTTP/1.1 206 Partial Content\r\n";
  const std::string fields = honest_head.substr(status_line.size());  // to the blank line
  const std::size_t n = options_.size;
  switch (options_.lie) {
    case Lie::kLongStatus:
      return sendAll(sock, "HTTP/1.1 206 " + std::string(n, 'x') + "\r\n" + fields + body) ? kKeep
                                                                                           : kClose;
    case Lie::kEndlessStatus:
      return sendEndless(sock, "HTTP/1.1 206 ", 'x') ? kKeep : kClose;
    case Lie::kLongHeader:
      return sendAll(sock, status_line + "X-Long: " + std::string(n, 'y') + "\r\n" + fields + body)
                 ? kKeep
                 : kClose;
    case Lie::kEndlessHeader:
      return sendEndless(sock, status_line + "X-Endless: ", 'y') ? kKeep : kClose;
    case Lie::kManyHeaders: {
      std::string many;
      for (std::size_t i = 0; i < n; ++i) many += "X-Field-" + std::to_string(i) + ": v\r\n";
      return sendAll(sock, status_line + many + fields + body) ? kKeep : kClose;
    }
    case Lie::kStatus:
      if (n == 200) {
        const std::string whole(file_.begin(), file_.end());
        sendAll(sock, "HTTP/1.1 200 OK\r\nContent-Length: " + std::to_string(whole.size()) +
                          "\r\n\r\n" + whole);
      } else {
        sendAll(sock, "HTTP/1.1 " + std::to_string(n) + " Something Went Wrong\r\n" +
                          "Content-Length: 5\r\n\r\noops!");
      }
      return kKeep;
    case Lie::kRedirect:
      sendAll(sock,
              "HTTP/1.1 301 Moved Permanently\r\nLocation: http://127.0.0.1:1/else.oct\r\n"
              "Content-Length: 0\r\n\r\n");
      return kKeep;
    case Lie::kCloseMidHead:
      sendAll(sock, honest_head.substr(0, std::min(n, honest_head.size() - 1)));
      return kClose;
    case Lie::kSilence:
      while (!stopping_) std::this_thread::sleep_for(std::chrono::milliseconds(20));
      return kClose;
    case Lie::kTrickle:
      for (char c : honest_head + body) {
        if (stopping_ || !sendAll(sock, std::string(1, c))) return kClose;
        std::this_thread::sleep_for(std::chrono::milliseconds(n));
      }
      return kKeep;
    default:
      return -1;
  }
}

// The lies about the range, its length and its body.
int HostileServer::lieAboutRange(int sock, std::uint64_t first, std::uint64_t last,
                                 const std::string& body) {
  const std::uint64_t total = file_.size();
  const std::size_t n = options_.size;
  const std::string ok_head = rangeHead(first, last, total, body.size());
  std::string sent;
  int verdict = kKeep;
  switch (options_.lie) {
    case Lie::kWrongOffset:
      sent = rangeHead(first + 1, last + 1, total + 1, body.size()) + body;
      break;
    case Lie::kWrongEnd:
      sent = rangeHead(first, last - 1, total, body.size() - 1) + body.substr(1);
      break;
    case Lie::kWrongTotal:
      sent = rangeHead(first, last, total + 1, body.size()) + body;
      break;
    case Lie::kGarbageRange:
      sent = "HTTP/1.1 206 Partial Content\r\nContent-Range: bytes garbage\r\nContent-Length: " +
             std::to_string(body.size()) + "\r\n\r\n" + body;
      break;
    case Lie::kShortLength:
      sent = rangeHead(first, last, total, body.size() - 1) + body.substr(1);
      break;
    case Lie::kLongLength:
      sent = rangeHead(first, last, total, body.size() + 1) + body + "z";
      break;
    case Lie::kTruncatedBody:
      sent = ok_head + body.substr(0, std::min(n, body.size() - 1));
      verdict = kClose;
      break;
    case Lie::kOverlongBody:
      sent = ok_head + body + std::string(n, 'z');
      break;
    case Lie::kReset:
      sent = ok_head + body.substr(0, std::min(n, body.size() - 1));
      verdict = kReset;
      break;
    case Lie::kChunkedEncoding:
      sent = "HTTP/1.1 206 Partial Content\r\nContent-Range: bytes " + std::to_string(first) + "-" +
             std::to_string(last) + "/" + std::to_string(total) +
             "\r\nTransfer-Encoding: chunked\r\n\r\n" + hex(body.size()) + "\r\n" + body +
             "\r\n0\r\n\r\n";
      break;
    case Lie::kDamage:
      sent = ok_head + body;
      sent[ok_head.size() + body.size() / 2] ^= 0x10;
      break;
    default:
      sent = ok_head + body;
  }
  if (!sendAll(sock, sent)) return kClose;
  if (verdict == kReset) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return verdict;
}

}  // namespace octopoint::testing
