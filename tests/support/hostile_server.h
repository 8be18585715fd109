#pragma once
// A hostile HTTP server of the tests' own, on 127.0.0.1 and a free port, on its own thread until
// destroyed: it serves one file by byte ranges and tells each lie a client may meet (a status line
// or a header without end, error statuses, redirects, a Content-Range or Content-Length that lies,
// a body cut or too long, a connection reset, silence, a trickle). The client must refuse each
// quickly, in a few words, with bounded memory (tests/net/hostile_server_test.cpp).

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace octopoint::testing {

enum class Lie {
  kNone,             // honest 206 answers
  kLongStatus,       // a reason phrase of `size` bytes
  kEndlessStatus,    // a status line that never ends
  kLongHeader,       // one header line of `size` bytes
  kEndlessHeader,    // a header line that never ends
  kManyHeaders,      // `size` short header fields
  kStatus,           // status `size` (500, 416, 200 (the whole file), 503, ...)
  kRedirect,         // 301 with a Location
  kWrongOffset,      // Content-Range starting a byte late
  kWrongEnd,         // Content-Range ending a byte early
  kWrongTotal,       // Content-Range total one byte more than the file
  kGarbageRange,     // Content-Range "bytes garbage"
  kShortLength,      // Content-Length one byte less than the range
  kLongLength,       // Content-Length one byte more, and a byte more of body
  kTruncatedBody,    // the body cut after `size` bytes, then the connection closed
  kOverlongBody,     // the range's body and `size` bytes more
  kCloseMidHead,     // the head cut after `size` bytes, then closed
  kReset,            // the head and `size` body bytes, then a reset (SO_LINGER 0)
  kSilence,          // reads the request, answers nothing, keeps the connection
  kTrickle,          // the honest answer, one byte every `size` milliseconds
  kChunkedEncoding,  // Transfer-Encoding: chunked
  kDamage,           // the honest head with a body byte flipped
};

struct HostileOptions {
  Lie lie = Lie::kNone;
  std::uint64_t size = 0;      // the lie's size or position (see Lie)
  std::uint64_t lie_from = 0;  // honest for ranges starting before this byte of the file
};

class HostileServer {
 public:
  HostileServer(std::vector<std::uint8_t> file, HostileOptions options);
  ~HostileServer();  // stops: every connection is closed, every thread joined
  HostileServer(const HostileServer&) = delete;
  HostileServer& operator=(const HostileServer&) = delete;
  int port() const { return port_; }
  int requests() const { return requests_.load(); }
  std::string url() const;  // http://127.0.0.1:PORT/model.oct

 private:
  void serve();
  void converse(int sock);
  // Each returns what to do with the connection then: keep it, close it, or reset it.
  int answer(int sock, std::uint64_t first, std::uint64_t last);
  int lieInHead(int sock, const std::string& honest_head, const std::string& body);
  int lieAboutRange(int sock, std::uint64_t first, std::uint64_t last, const std::string& body);
  bool sendAll(int sock, const std::string& bytes);
  bool sendEndless(int sock, const std::string& prefix, char filler);

  std::vector<std::uint8_t> file_;
  HostileOptions options_;
  int listener_ = -1;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::atomic<int> requests_{0};
  std::mutex mutex_;
  std::vector<std::thread> connections_;
  std::thread thread_;
};

}  // namespace octopoint::testing
