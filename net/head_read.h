#pragma once
// Reading a chunked file's head over byte ranges, for the streams (net/model_stream.cpp,
// net/scene_stream.cpp): the first request asks for the file's first bytes (more than the head, so
// that the coarse levels' tables and chunks often come with it); once the fixed header is in, it
// says the head's size, and the rest of the head is asked for; then the model is made. The bytes
// are kept: later ranges may start in them, and those parts are not asked for again.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "octopoint/progressive.h"

namespace octopoint::net {

class HeadRead {
 public:
  struct Range {
    std::uint64_t offset = 0;
    std::uint64_t size = 0;
  };
  // The next range to ask for: from the bytes held on, to the head's end once its size is known,
  // else `first_request_bytes` in all; at least the fixed header, and at least a byte.
  Range nextRange(std::uint64_t first_request_bytes) const;

  // Takes the next bytes of the head's request. Returns the model the first time the bytes hold
  // the whole head; nullopt before, and for a head that fails validation (then `*issue` says why
  // and failed() is true).
  std::optional<ProgressiveModel> take(std::span<const std::uint8_t> piece, ChunkedIssue* issue);

  // The bytes held of [offset, offset + size): what a range starting in them need not ask for.
  std::vector<std::uint8_t> known(std::uint64_t offset, std::uint64_t size) const;

  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  bool failed() const { return failed_; }
  bool in_flight = false;  // a head request is out (its owner's flag, under its lock)

 private:
  std::vector<std::uint8_t> bytes_;  // the file's first bytes
  std::uint64_t head_bytes_ = 0;     // the head's size, once the fixed header is in
  bool made_ = false, failed_ = false;
};

// A model that is not there: an answer of 4xx to its head's request, other than 408 (request
// timeout) and 429 (too many requests), which say "later", not "never".
bool headMissing(int http_status);

// "URL: what (byte N)": a stream's message for a chunked issue.
std::string describeAt(const std::string& url, const ChunkedIssue& issue);

}  // namespace octopoint::net
