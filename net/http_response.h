#pragma once
// The head of an HTTP/1.1 response (status line and header fields, RFC 9112), read incrementally
// from untrusted bytes with hard limits, so that no server can make the client hold more than
// kMaxHeadBytes for it or parse a line longer than kMaxLineBytes. A pure function of the bytes fed:
// no socket, no clock (the fuzzer fuzz/http_response_fuzzer.cpp feeds it directly).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace octopoint::net {

struct ResponseLimits {
  std::size_t max_line_bytes = 8 * 1024;   // the status line, and each header line
  std::size_t max_headers = 100;           // header fields
  std::size_t max_head_bytes = 64 * 1024;  // status line, headers and the blank line together
};

struct ResponseHead {
  int status = 0;
  std::string reason;  // printable ASCII only (anything else is replaced by '?'), at most 200 bytes
  std::vector<std::pair<std::string, std::string>> headers;  // names in lower case
  // The value of the one field named `name` (lower case); nullopt when absent. A field given
  // twice with different values counts as absent and sets *repeated.
  std::optional<std::string> field(std::string_view name, bool* repeated = nullptr) const;
};

class ResponseHeadParser {
 public:
  enum class State { kNeedMore, kDone, kError };
  explicit ResponseHeadParser(const ResponseLimits& limits = {}) : limits_(limits) {}

  // Takes the next bytes of the response; returns how many it used. Once kDone, the bytes after
  // the head (the body's first bytes) are not used: they start at data + the returned count.
  std::size_t feed(std::string_view data);
  State state() const { return state_; }
  const ResponseHead& head() const { return head_; }
  const std::string& error() const { return error_; }  // when kError: what was wrong, in words
  std::size_t headBytes() const { return total_; }

 private:
  void takeLine(std::string_view line);
  void failWith(std::string why);

  ResponseLimits limits_;
  State state_ = State::kNeedMore;
  ResponseHead head_;
  std::string line_;  // the line being read, at most max_line_bytes
  std::size_t total_ = 0;
  bool status_read_ = false;
  std::string error_;
};

// How the body's length is known (RFC 9112, 6.3), for a response to a GET.
struct BodyLength {
  enum class Kind { kNone, kLength, kUntilClose } kind = Kind::kNone;
  std::uint64_t bytes = 0;  // for kLength
};
// nullopt, with `error` saying why, for a Transfer-Encoding (not accepted: a byte range has a known
// length, and every static server sends it as Content-Length), a repeated or malformed
// Content-Length.
std::optional<BodyLength> bodyLength(const ResponseHead& head, std::string* error);

// "bytes FIRST-LAST/TOTAL" or "bytes FIRST-LAST/*" (total 0), FIRST <= LAST, LAST < TOTAL; false
// for anything else.
bool parseContentRange(std::string_view text, std::uint64_t* first, std::uint64_t* last,
                       std::uint64_t* total);

// Digits only, at most 19 of them; nullopt for anything else, including "".
std::optional<std::uint64_t> parseDecimal(std::string_view text);

}  // namespace octopoint::net
