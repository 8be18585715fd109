// The client's side of HTTP: our own small HTTP/1.1 client over POSIX sockets
// (net/http_connection.h for the socket, net/http_response.h for the response head), bounded
// everywhere, because the library it replaced (cpp-httplib 0.11.4) read status lines and headers
// without any bound and crashed on a long status line (docs/robustness.md, "The HTTP client").
#include <algorithm>
#include <array>
#include <mutex>

#include "net/http_connection.h"
#include "net/http_response.h"
#include "octopoint/http.h"

namespace octopoint::net {
namespace {

using Clock = std::chrono::steady_clock;
using Sink = std::function<bool(std::uint64_t, std::span<const std::uint8_t>)>;

std::string statusText(const ResponseHead& head) {
  return std::to_string(head.status) + (head.reason.empty() ? "" : " " + head.reason);
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
  Impl(const HttpUrl& url, const RangeTimeouts& timeouts) : url_(url), timeouts_(timeouts) {}

  FetchResult fetch(std::uint64_t offset, std::uint64_t size, const Sink& sink,
                    const std::atomic<bool>* cancel) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      busy_ = true;
    }
    FetchResult result;
    if (size == 0) {
      result.status = FetchStatus::kBadResponse;
      result.message = "an empty range was asked for";
    } else {
      // A connection kept alive may have been closed by the server meanwhile: that is found
      // before any byte of the answer arrives, and the request is made once more on a new one.
      bool stale = false;
      result = attempt(offset, size, sink, cancel, &stale);
      if (stale) result = attempt(offset, size, sink, cancel, &stale);
    }
    if (result.status != FetchStatus::kOk) connection_.close();
    std::lock_guard<std::mutex> lock(mutex_);
    busy_ = false;
    connection_.clearAbort();
    return result;
  }

  void abort() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (busy_)
      connection_.abort();
    else
      connection_.close();
  }

 private:
  struct Request {
    std::uint64_t offset, size;
    const Sink& sink;
    const std::atomic<bool>* cancel;
    Clock::time_point deadline;  // for the whole request: a grace period, then the minimum rate
    FetchResult& result;
  };

  FetchResult fail(FetchResult& result, FetchStatus status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    return result;
  }

  // The next bytes, waiting at most until the request's deadline and read_seconds of silence.
  HttpConnection::Io receive(const Request& request) {
    const Clock::time_point stall = Clock::now() + std::chrono::seconds(timeouts_.read_seconds);
    return connection_.receive(buffer_, std::min(stall, request.deadline));
  }

  std::string slowness(const Request& request) const {
    return Clock::now() >= request.deadline
               ? "slower than " + std::to_string(timeouts_.min_bytes_per_second) + " bytes/s (" +
                     std::to_string(request.result.bytes) + " of " + std::to_string(request.size) +
                     " bytes)"
               : "no byte for " + std::to_string(timeouts_.read_seconds) + " s";
  }

  FetchResult attempt(std::uint64_t offset, std::uint64_t size, const Sink& sink,
                      const std::atomic<bool>* cancel, bool* stale) {
    const bool reused = connection_.connected();
    *stale = false;
    FetchResult result;
    const Clock::time_point start = Clock::now();
    const Request request{
        offset,
        size,
        sink,
        cancel,
        start + std::chrono::seconds(timeouts_.read_seconds) +
            std::chrono::seconds(size / std::max<std::uint64_t>(timeouts_.min_bytes_per_second, 1)),
        result};
    if (!reused) {
      const std::string why = connection_.connect(
          url_.host, url_.port, start + std::chrono::seconds(timeouts_.connect_seconds));
      if (!why.empty()) return fail(result, FetchStatus::kConnectionFailed, why);
    }
    const std::string text = "GET " + url_.path + " HTTP/1.1\r\nHost: " + hostHeader() +
                             "\r\nRange: bytes=" + std::to_string(offset) + "-" +
                             std::to_string(offset + size - 1) +
                             "\r\nAccept-Encoding: identity\r\nUser-Agent: octopoint\r\n\r\n";
    const HttpConnection::Io sent = connection_.send(text, request.deadline);
    if (sent.outcome != HttpConnection::Outcome::kDone) {
      *stale = reused && sent.outcome == HttpConnection::Outcome::kError;
      if (*stale) connection_.close();
      return fail(result, transportStatus(sent.outcome),
                  sent.error.empty() ? "cannot send the request" : sent.error);
    }
    ResponseHeadParser parser;
    std::string_view body_start;
    if (!readHead(request, parser, reused, stale, &body_start)) return result;
    if (!checkHead(request, parser.head())) return result;
    readBody(request, body_start);
    return result;
  }

  static FetchStatus transportStatus(HttpConnection::Outcome outcome) {
    switch (outcome) {
      case HttpConnection::Outcome::kTimeout:
        return FetchStatus::kTooSlow;
      case HttpConnection::Outcome::kAborted:
        return FetchStatus::kCancelled;
      default:
        return FetchStatus::kConnectionFailed;
    }
  }

  std::string hostHeader() const {
    const std::string host =
        url_.host.find(':') != std::string::npos ? "[" + url_.host + "]" : url_.host;
    return url_.port == 80 ? host : host + ":" + std::to_string(url_.port);
  }

  bool readHead(const Request& request, ResponseHeadParser& parser, bool reused, bool* stale,
                std::string_view* body_start);
  bool checkHead(const Request& request, const ResponseHead& head);
  void readBody(const Request& request, std::string_view first);
  bool deliver(const Request& request, std::string_view piece);

  HttpUrl url_;
  RangeTimeouts timeouts_;
  HttpConnection connection_;
  std::array<char, 16 * 1024> buffer_{};
  std::uint64_t expected_ = 0;  // the body's length, from the checked head
  bool until_close_ = false;    // no Content-Length: the body ends when the server closes
  bool close_after_ = false;    // "Connection: close", or no length
  std::mutex mutex_;
  bool busy_ = false;
};

// Reads up to the end of the head. False (with the result set) when it did not come whole.
bool RangeClient::Impl::readHead(const Request& request, ResponseHeadParser& parser, bool reused,
                                 bool* stale, std::string_view* body_start) {
  bool any = false;
  while (parser.state() == ResponseHeadParser::State::kNeedMore) {
    const HttpConnection::Io got = receive(request);
    if (got.outcome == HttpConnection::Outcome::kClosed ||
        got.outcome == HttpConnection::Outcome::kError) {
      *stale = reused && !any;
      if (*stale) connection_.close();
      const std::string how = got.outcome == HttpConnection::Outcome::kClosed
                                  ? "closed the connection"
                                  : "broke the connection (" + got.error + ")";
      fail(request.result, FetchStatus::kConnectionFailed,
           "the server " + how +
               (any ? " in the middle of the response head" : " without answering"));
      return false;
    }
    if (got.outcome == HttpConnection::Outcome::kTimeout) {
      fail(request.result, FetchStatus::kTooSlow,
           "no complete response head: " + slowness(request));
      return false;
    }
    if (got.outcome == HttpConnection::Outcome::kAborted) {
      fail(request.result, FetchStatus::kCancelled, "cancelled");
      return false;
    }
    any = true;
    const std::string_view data(buffer_.data(), got.bytes);
    const std::size_t used = parser.feed(data);
    if (parser.state() == ResponseHeadParser::State::kError) {
      fail(request.result, FetchStatus::kBadResponse, "the server sent " + parser.error());
      return false;
    }
    *body_start = data.substr(used);
  }
  return true;
}

// The status and the range the head declares, against what was asked.
bool RangeClient::Impl::checkHead(const Request& request, const ResponseHead& head) {
  FetchResult& result = request.result;
  result.http_status = head.status;
  const std::uint64_t asked_last = request.offset + request.size - 1;
  std::string why;
  const std::optional<BodyLength> length = bodyLength(head, &why);
  if (head.status != 206 && !(head.status == 200 && request.offset == 0)) {
    std::string message = "the server answered " + statusText(head);
    if (head.status >= 300 && head.status < 400)
      message += ", a redirect to '" + head.field("location").value_or("") + "' (not followed)";
    else if (head.status == 200)
      message += " (the whole file) to a request for a range";
    fail(result, FetchStatus::kHttpStatus, message);
    return false;
  }
  if (!length) {
    fail(result, FetchStatus::kBadResponse, "the server sent " + why);
    return false;
  }
  if (head.status == 206) {
    std::uint64_t first = 0, last = 0, total = 0;
    const std::optional<std::string> range = head.field("content-range");
    // A range cut at the file's end is what a server must answer when the file is shorter.
    if (!range || !parseContentRange(*range, &first, &last, &total) || first != request.offset ||
        !(last == asked_last || (last < asked_last && total != 0 && last == total - 1))) {
      fail(result, FetchStatus::kBadResponse,
           "the server sent Content-Range '" + range.value_or("(none)").substr(0, 80) +
               "' for bytes " + std::to_string(request.offset) + "-" + std::to_string(asked_last));
      return false;
    }
    result.file_size = total;
    expected_ = last - first + 1;
  } else {
    expected_ = length->kind == BodyLength::Kind::kLength ? length->bytes : request.size;
    if (length->kind == BodyLength::Kind::kLength && length->bytes > request.size) {
      fail(result, FetchStatus::kTooLong,
           "the server answered 200 with the whole file, " + std::to_string(length->bytes) +
               " bytes, where " + std::to_string(request.size) + " were asked for");
      return false;
    }
    if (length->kind == BodyLength::Kind::kLength) result.file_size = length->bytes;
  }
  if (length->kind == BodyLength::Kind::kLength && length->bytes != expected_) {
    fail(result, FetchStatus::kBadResponse,
         "the server sent Content-Length " + std::to_string(length->bytes) + " for a range of " +
             std::to_string(expected_) + " bytes");
    return false;
  }
  until_close_ = length->kind != BodyLength::Kind::kLength;
  const std::optional<std::string> connection = head.field("connection");
  close_after_ = until_close_ || (connection && connection->find("close") != std::string::npos);
  return true;
}

// Hands `piece` to the sink; false (with the result set) when it ends the fetch.
bool RangeClient::Impl::deliver(const Request& request, std::string_view piece) {
  FetchResult& result = request.result;
  if (request.cancel != nullptr && request.cancel->load(std::memory_order_relaxed)) {
    fail(result, FetchStatus::kCancelled, "cancelled");
    return false;
  }
  const std::size_t useful =
      static_cast<std::size_t>(std::min<std::uint64_t>(piece.size(), expected_ - result.bytes));
  if (useful > 0) {
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(piece.data()),
                                              useful);
    if (!request.sink(request.offset + result.bytes, bytes)) {
      fail(result, FetchStatus::kCancelled, "cancelled");
      return false;
    }
    result.bytes += useful;
  }
  if (useful < piece.size()) {
    fail(result, FetchStatus::kTooLong,
         "the server sent more than the " + std::to_string(expected_) + " bytes it announced");
    return false;
  }
  return true;
}

void RangeClient::Impl::readBody(const Request& request, std::string_view first) {
  FetchResult& result = request.result;
  if (!deliver(request, first)) return;
  while (result.bytes < expected_) {
    const HttpConnection::Io got = receive(request);
    if (got.outcome == HttpConnection::Outcome::kDone) {
      if (!deliver(request, std::string_view(buffer_.data(), got.bytes))) return;
      continue;
    }
    const std::string so_far =
        " after " + std::to_string(result.bytes) + " of " + std::to_string(expected_) + " bytes";
    if (got.outcome == HttpConnection::Outcome::kTimeout) {
      fail(result, FetchStatus::kTooSlow, "the body came too slowly: " + slowness(request));
    } else if (got.outcome == HttpConnection::Outcome::kAborted) {
      fail(result, FetchStatus::kCancelled, "cancelled");
    } else if (until_close_ && got.outcome == HttpConnection::Outcome::kClosed) {
      break;  // a body without a length ends here: as long as the range, or short
    } else {
      fail(result, FetchStatus::kTooShort,
           got.outcome == HttpConnection::Outcome::kClosed
               ? "the server closed the connection" + so_far
               : "the server broke the connection (" + got.error + ")" + so_far);
    }
    return;
  }
  if (result.bytes != expected_) {
    fail(result, FetchStatus::kTooShort,
         "the body ended after " + std::to_string(result.bytes) + " of " +
             std::to_string(expected_) + " bytes");
    return;
  }
  if (!close_after_) {
    // Bytes already waiting past the body would be read as the next response: too long.
    char probe = 0;
    const HttpConnection::Io more = connection_.receive({&probe, 1}, Clock::now());
    if (more.outcome == HttpConnection::Outcome::kDone) {
      fail(result, FetchStatus::kTooLong,
           "the server sent more than the " + std::to_string(expected_) + " bytes it announced");
      return;
    }
    close_after_ = more.outcome != HttpConnection::Outcome::kTimeout;  // closed or broken
  }
  result.status = FetchStatus::kOk;
  result.message = describe(FetchStatus::kOk);
  if (close_after_) connection_.close();
}

RangeClient::RangeClient(const HttpUrl& url, const RangeTimeouts& timeouts)
    : impl_(std::make_unique<Impl>(url, timeouts)) {}
RangeClient::~RangeClient() = default;

FetchResult RangeClient::fetch(std::uint64_t offset, std::uint64_t size, const Sink& sink,
                               const std::atomic<bool>* cancel) {
  return impl_->fetch(offset, size, sink, cancel);
}

void RangeClient::abort() { impl_->abort(); }

}  // namespace octopoint::net
