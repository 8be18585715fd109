#include "codegen/lzf_check.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

// The compressed bytes through a window of the file: at least three bytes (the longest token
// head) are in it whenever that many are left. A 1 GiB stream is walked in about a second.
class Window {
 public:
  Window(const fs::path& path, std::uint64_t offset, std::uint64_t size)
      : path_(path), in_(path, std::ios::binary), base_(offset), end_(offset + size) {
    in_.seekg(static_cast<std::streamoff>(offset));
  }

  // The file byte of the next unread byte, and the bytes left after it.
  std::uint64_t at() const { return base_ + pos_; }
  std::uint64_t left() const { return end_ - at(); }

  // The next bytes, at least min(3, left()) of them (and pointing at the window's end when none).
  const unsigned char* head() {
    if (have_ - pos_ < 3 && loaded() < end_) refill();
    return buffer_.data() + pos_;
  }

  // Moves past `n` bytes (at most left()).
  void skip(std::uint64_t n) {
    while (n > have_ - pos_) {
      n -= have_ - pos_;
      pos_ = have_;
      refill();
    }
    pos_ += static_cast<std::size_t>(n);
  }

 private:
  std::uint64_t loaded() const { return base_ + have_; }

  // Keeps the unread bytes, then reads as many more as fit and are left.
  void refill() {
    const std::size_t kept = have_ - pos_;
    std::memmove(buffer_.data(), buffer_.data() + pos_, kept);
    base_ += pos_;
    pos_ = 0;
    have_ = kept;
    const std::uint64_t wanted = std::min<std::uint64_t>(buffer_.size() - kept, end_ - loaded());
    in_.read(reinterpret_cast<char*>(buffer_.data() + kept), static_cast<std::streamsize>(wanted));
    have_ = kept + static_cast<std::size_t>(in_.gcount());
    // checkPcdCompressedBody found these bytes in the file: a short read means it shrank since.
    if (have_ - kept != wanted) {
      fail(path_, "the file shrank while it was read", "byte " + std::to_string(loaded()));
    }
  }

  const fs::path& path_;
  std::ifstream in_;
  std::uint64_t base_;  // the file byte of buffer_[0]
  std::uint64_t end_;
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(1 << 20);
  std::size_t have_ = 0;
  std::size_t pos_ = 0;
};

}  // namespace

void checkLzfStream(const fs::path& path, std::uint64_t offset, std::uint64_t compressed,
                    std::uint64_t uncompressed) {
  Window in(path, offset, compressed);
  auto failAt = [&](const std::string& why, std::uint64_t byte) {
    fail(path, "corrupt: binary_compressed data " + why, "data at byte " + std::to_string(byte));
  };
  std::uint64_t out = 0;  // bytes the stream has expanded to so far
  while (in.left() > 0) {
    const std::uint64_t start = in.at();
    const std::uint64_t left = in.left();
    const unsigned char* head = in.head();
    const unsigned control = head[0];
    if (control < 32) {  // a literal run of control + 1 bytes
      const std::uint64_t run = control + 1;
      if (run > left - 1) failAt("ends inside a literal run", start);
      in.skip(1 + run);
      out += run;
    } else {  // a back reference: length - 2 in the top 3 bits (7: one more byte adds to it)
      const bool long_form = control >> 5 == 7;
      const std::uint64_t head_bytes = long_form ? 3 : 2;
      if (left <= head_bytes - 1) failAt("ends inside a back reference", start);
      const std::uint64_t length = (control >> 5) + (long_form ? head[1] : 0);
      // distance - 1 in the low 5 bits and the next byte
      const std::uint64_t distance = ((control & 0x1fu) << 8) + head[head_bytes - 1] + 1;
      if (distance > out) {
        failAt("refers " + std::to_string(distance) + " bytes back after " + std::to_string(out) +
                   " bytes of output, before its start",
               start);
      }
      in.skip(head_bytes);
      out += length + 2;
    }
    if (out > uncompressed) {
      failAt("expands past the " + std::to_string(uncompressed) + " bytes it declares", start);
    }
  }
  if (out != uncompressed) {
    failAt("expands to " + std::to_string(out) + " bytes, not the " + std::to_string(uncompressed) +
               " it declares",
           offset);
  }
}

}  // namespace octopoint::prepare
