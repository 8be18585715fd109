// libFuzzer harness for the HTTP client's response parsing (net/http_response.h): the head parser
// fed the input in pieces whose sizes the input's first byte chooses, then the body length and the
// Content-Range read from what it parsed. No input may crash it, make it hold more than its limits
// (64 KiB of head) or disagree with itself on where the head ends.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "net/http_response.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t piece = 1 + data[0] % 64;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  octopoint::net::ResponseHeadParser parser;
  std::size_t at = 0;
  while (at < text.size() &&
         parser.state() == octopoint::net::ResponseHeadParser::State::kNeedMore) {
    const std::string_view next = text.substr(at, piece);
    const std::size_t used = parser.feed(next);
    if (used > next.size()) __builtin_trap();
    at += used;
    if (used < next.size() &&
        parser.state() == octopoint::net::ResponseHeadParser::State::kNeedMore)
      __builtin_trap();  // it left bytes unread without deciding
  }
  if (parser.headBytes() > 64 * 1024) __builtin_trap();
  if (parser.state() != octopoint::net::ResponseHeadParser::State::kDone) return 0;
  std::string error;
  static_cast<void>(octopoint::net::bodyLength(parser.head(), &error));
  if (const auto range = parser.head().field("content-range")) {
    std::uint64_t first = 0, last = 0, total = 0;
    if (octopoint::net::parseContentRange(*range, &first, &last, &total) &&
        (first > last || (total != 0 && last >= total)))
      __builtin_trap();
  }
  return 0;
}
