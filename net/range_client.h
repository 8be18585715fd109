#pragma once
// Fetching byte ranges of one file over HTTP/1.1 (cpp-httplib), from any static server with Range
// support (octopoint-serve, nginx, ...), trusting nothing the server says: the status must be 206
// with a Content-Range naming exactly the bytes asked for (or 200 with the whole file when that is
// what was asked), the body must be exactly that long (a longer or endless body is cut off and
// refused), and it must arrive at a useful rate (cut off otherwise). One connection, kept alive.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "net/http_url.h"

namespace octopoint::net {

struct RangeTimeouts {
  int connect_seconds = 5;
  int read_seconds = 10;                     // no byte for this long: the fetch fails
  std::uint64_t min_bytes_per_second = 256;  // a body slower than this (after 10 s of grace) fails
};

enum class FetchStatus {
  kOk,
  kConnectionFailed,  // could not connect, or the connection broke
  kHttpStatus,        // the server answered with another status (404, 416, 503, ...)
  kBadResponse,       // a Content-Range or Content-Length that is not what was asked
  kTooLong,           // more bytes than asked (an endless or oversized body)
  kTooShort,          // the body ended early
  kTooSlow,           // below the minimum rate, or stalled
  kCancelled,         // the caller's cancel flag
};

const char* describe(FetchStatus status);

struct FetchResult {
  FetchStatus status = FetchStatus::kOk;
  int http_status = 0;
  std::uint64_t bytes = 0;      // body bytes received (passed to the sink)
  std::uint64_t file_size = 0;  // from Content-Range, when the server said
  std::string message;          // one line for logs
};

class RangeClient {
 public:
  RangeClient(const HttpUrl& url, const RangeTimeouts& timeouts);
  ~RangeClient();
  RangeClient(const RangeClient&) = delete;
  RangeClient& operator=(const RangeClient&) = delete;

  // Fetches bytes [offset, offset + size) of the URL's file. `sink(offset_of_piece, piece)` sees
  // the body as it arrives, in order; returning false from it cancels. `cancel`, when given and
  // set, ends the fetch at the next piece.
  FetchResult fetch(std::uint64_t offset, std::uint64_t size,
                    const std::function<bool(std::uint64_t, std::span<const std::uint8_t>)>& sink,
                    const std::atomic<bool>* cancel = nullptr);
  // From another thread: breaks the connection, so that a fetch blocked on it ends at once.
  void abort();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace octopoint::net
