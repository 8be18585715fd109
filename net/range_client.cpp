#include <httplib.h>

#include <chrono>
#include <cinttypes>
#include <cstdio>

#include "octopoint/http.h"

namespace octopoint::net {
namespace {

using Clock = std::chrono::steady_clock;

// "bytes FIRST-LAST/TOTAL" (TOTAL may be "*"); false when it is anything else.
bool parseContentRange(const std::string& text, std::uint64_t* first, std::uint64_t* last,
                       std::uint64_t* total) {
  unsigned long long a = 0, b = 0, t = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "bytes %llu-%llu/%llu%c", &a, &b, &t, &tail) == 3) {
    *total = t;
  } else if (std::sscanf(text.c_str(), "bytes %llu-%llu/*%c", &a, &b, &tail) == 2) {
    *total = 0;
  } else {
    return false;
  }
  *first = a;
  *last = b;
  return true;
}

}  // namespace

const char* describe(FetchStatus status) {
  switch (status) {
    case FetchStatus::kOk:
      return "ok";
    case FetchStatus::kConnectionFailed:
      return "connection failed";
    case FetchStatus::kHttpStatus:
      return "unexpected HTTP status";
    case FetchStatus::kBadResponse:
      return "response headers do not match the range asked for";
    case FetchStatus::kTooLong:
      return "more bytes than asked for";
    case FetchStatus::kTooShort:
      return "fewer bytes than asked for";
    case FetchStatus::kTooSlow:
      return "too slow";
    case FetchStatus::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

class RangeClient::Impl {
 public:
  Impl(const HttpUrl& url, const RangeTimeouts& timeouts)
      : url_(url), timeouts_(timeouts), client_(url.host, url.port) {
    client_.set_connection_timeout(timeouts.connect_seconds);
    client_.set_read_timeout(timeouts.read_seconds);
    client_.set_write_timeout(timeouts.read_seconds);
    client_.set_keep_alive(true);
    client_.set_tcp_nodelay(true);  // a request goes out whole at once, never behind an ACK
    client_.set_decompress(false);
    client_.set_follow_location(false);
  }

  FetchResult fetch(std::uint64_t offset, std::uint64_t size,
                    const std::function<bool(std::uint64_t, std::span<const std::uint8_t>)>& sink,
                    const std::atomic<bool>* cancel) {
    FetchResult result;
    FetchStatus verdict = FetchStatus::kOk;
    const std::uint64_t last = offset + size - 1;
    const httplib::Headers headers = {
        {"Range", "bytes=" + std::to_string(offset) + "-" + std::to_string(last)},
        {"Accept-Encoding", "identity"}};
    const Clock::time_point start = Clock::now();
    // A body slower than the minimum rate, after a grace period, is given up.
    const auto deadline =
        start + std::chrono::seconds(10) +
        std::chrono::seconds(size / std::max<std::uint64_t>(timeouts_.min_bytes_per_second, 1));
    const auto on_response = [&](const httplib::Response& response) {
      result.http_status = response.status;
      const bool whole = response.status == 200 && offset == 0;
      if (response.status != 206 && !whole) {
        verdict = FetchStatus::kHttpStatus;
        return false;
      }
      if (response.status == 206) {
        std::uint64_t first = 0, end = 0, total = 0;
        if (!parseContentRange(response.get_header_value("Content-Range"), &first, &end, &total) ||
            first != offset || end != last) {
          verdict = FetchStatus::kBadResponse;
          return false;
        }
        result.file_size = total;
      }
      if (response.has_header("Content-Length")) {
        const std::string length = response.get_header_value("Content-Length");
        if (length != std::to_string(size)) {
          verdict = whole ? FetchStatus::kTooLong : FetchStatus::kBadResponse;
          return false;
        }
      }
      return true;
    };
    const auto on_body = [&](const char* data, std::size_t length) {
      if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
        verdict = FetchStatus::kCancelled;
        return false;
      }
      if (result.bytes + length > size) {
        verdict = FetchStatus::kTooLong;
        return false;
      }
      if (Clock::now() > deadline) {
        verdict = FetchStatus::kTooSlow;
        return false;
      }
      const std::span<const std::uint8_t> piece(reinterpret_cast<const std::uint8_t*>(data),
                                                length);
      if (!sink(offset + result.bytes, piece)) {
        verdict = FetchStatus::kCancelled;
        return false;
      }
      result.bytes += length;
      return true;
    };
    const httplib::Result response = client_.Get(url_.path, headers, on_response, on_body);
    if (verdict == FetchStatus::kOk && !response) {
      verdict = response.error() == httplib::Error::Read && result.http_status != 0
                    ? FetchStatus::kTooShort
                    : FetchStatus::kConnectionFailed;
      result.message = httplib::to_string(response.error());
    }
    if (verdict == FetchStatus::kOk && result.bytes != size) verdict = FetchStatus::kTooShort;
    if (verdict != FetchStatus::kOk) client_.stop();  // never reuse a connection left mid-response
    result.status = verdict;
    if (result.message.empty()) result.message = describe(verdict);
    return result;
  }

  void abort() { client_.stop(); }

 private:
  HttpUrl url_;
  RangeTimeouts timeouts_;
  httplib::Client client_;
};

RangeClient::RangeClient(const HttpUrl& url, const RangeTimeouts& timeouts)
    : impl_(std::make_unique<Impl>(url, timeouts)) {}
RangeClient::~RangeClient() = default;

FetchResult RangeClient::fetch(
    std::uint64_t offset, std::uint64_t size,
    const std::function<bool(std::uint64_t, std::span<const std::uint8_t>)>& sink,
    const std::atomic<bool>* cancel) {
  return impl_->fetch(offset, size, sink, cancel);
}

void RangeClient::abort() { impl_->abort(); }

}  // namespace octopoint::net
