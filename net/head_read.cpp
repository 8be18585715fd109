#include "net/head_read.h"

#include <algorithm>

namespace octopoint::net {

HeadRead::Range HeadRead::nextRange(std::uint64_t first_request_bytes) const {
  std::uint64_t want = head_bytes_ > 0 ? head_bytes_ : first_request_bytes;
  want = std::max<std::uint64_t>(want, chunked::kFixedHeaderBytes);
  if (want <= bytes_.size()) want = bytes_.size() + 1;
  return {bytes_.size(), want - bytes_.size()};
}

std::optional<ProgressiveModel> HeadRead::take(std::span<const std::uint8_t> piece,
                                               ChunkedIssue* issue) {
  bytes_.insert(bytes_.end(), piece.begin(), piece.end());
  if (made_ || failed_) return std::nullopt;
  if (head_bytes_ == 0 && bytes_.size() >= chunked::kFixedHeaderBytes) {
    const std::optional<std::uint64_t> size = chunkedHeadBytes(bytes_, issue);
    if (!size) {
      failed_ = true;
      return std::nullopt;
    }
    head_bytes_ = *size;
  }
  if (head_bytes_ == 0 || bytes_.size() < head_bytes_) return std::nullopt;
  std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(bytes_, issue);
  made_ = model.has_value();
  failed_ = !made_;
  return model;
}

std::vector<std::uint8_t> HeadRead::known(std::uint64_t offset, std::uint64_t size) const {
  if (offset >= bytes_.size()) return {};
  const std::uint64_t count = std::min<std::uint64_t>(bytes_.size() - offset, size);
  return {bytes_.begin() + static_cast<std::ptrdiff_t>(offset),
          bytes_.begin() + static_cast<std::ptrdiff_t>(offset + count)};
}

bool headMissing(int http_status) {
  return http_status >= 400 && http_status < 500 && http_status != 408 && http_status != 429;
}

std::string describeAt(const std::string& url, const ChunkedIssue& issue) {
  return url + ": " + describe(issue.error) + " (byte " + std::to_string(issue.offset) + ")";
}

}  // namespace octopoint::net
