#include "codegen/byte_text.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string_view>

#include "codegen/parallel.h"

namespace octopoint::prepare {
namespace {

constexpr std::size_t kPieceBytes = std::size_t{1} << 20;  // bytes spelled by one task

// A byte's spelling: its characters (padded to 4, so that a copy of 4 is always allowed inside a
// piece) and how many of them count.
struct Spelling {
  std::array<char, 4> chars;
  std::size_t size;
};

struct Style {
  std::string_view start, line_break, end;
  std::array<Spelling, 256> spellings;
};

constexpr Style makeStrings() {
  Style style{"    \"", "\"\n    \"", "\"\n", {}};
  for (unsigned byte = 0; byte < 256; ++byte) {
    const bool plain = byte >= 0x20 && byte < 0x7f && byte != '"' && byte != '\\' && byte != '?';
    Spelling& s = style.spellings[byte];
    if (plain) {
      s = {{static_cast<char>(byte), ' ', ' ', ' '}, 1};
    } else {
      s = {{'\\', static_cast<char>('0' + (byte >> 6)), static_cast<char>('0' + ((byte >> 3) & 7)),
            static_cast<char>('0' + (byte & 7))},
           4};
    }
  }
  return style;
}

constexpr Style makeBytes() {
  Style style{"    ", "\n    ", "\n", {}};
  for (unsigned byte = 0; byte < 256; ++byte) {
    Spelling& s = style.spellings[byte];
    if (byte >= 100) {
      s = {{static_cast<char>('0' + byte / 100), static_cast<char>('0' + byte / 10 % 10),
            static_cast<char>('0' + byte % 10), ','},
           4};
    } else if (byte >= 10) {
      s = {{static_cast<char>('0' + byte / 10), static_cast<char>('0' + byte % 10), ',', ' '}, 3};
    } else {
      s = {{static_cast<char>('0' + byte), ',', ' ', ' '}, 2};
    }
  }
  return style;
}

constexpr Style kStrings = makeStrings();
constexpr Style kBytes = makeBytes();
static_assert(kLineWidth < kMaxLiteralPiece);

const Style& styleOf(EmitStyle style) { return style == EmitStyle::kStrings ? kStrings : kBytes; }

}  // namespace

ByteText::ByteText(std::span<const std::uint8_t> bytes, EmitStyle style)
    : bytes_(bytes), style_(style) {
  const Style& s = styleOf(style);
  std::size_t offset = s.start.size();
  std::size_t column = 0;
  checkpoints_.reserve(bytes.size() / kPieceBytes + 1);
  for (std::size_t begin = 0; begin < bytes.size(); begin += kPieceBytes) {
    checkpoints_.push_back({offset, column});
    const std::size_t end = std::min(bytes.size(), begin + kPieceBytes);
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t size = s.spellings[bytes[i]].size;
      if (column + size > kLineWidth) {
        offset += s.line_break.size();
        column = 0;
      }
      column += size;
      offset += size;
    }
  }
  size_ = offset + s.end.size();
}

void ByteText::writePiece(std::size_t piece, char* text) const {
  const Style& s = styleOf(style_);
  const std::size_t begin = piece * kPieceBytes;
  const std::size_t end = std::min(bytes_.size(), begin + kPieceBytes);
  // The last 3 bytes are copied at their own size: a 4-character copy there could run into the
  // next piece, which another thread writes.
  const std::size_t padded_end = end - std::min<std::size_t>(end - begin, 3);
  char* out = text + checkpoints_[piece].offset;
  std::size_t column = checkpoints_[piece].column;
  const auto spell = [&](std::size_t i, auto copy) {
    const Spelling& spelling = s.spellings[bytes_[i]];
    if (column + spelling.size > kLineWidth) {
      std::memcpy(out, s.line_break.data(), s.line_break.size());
      out += s.line_break.size();
      column = 0;
    }
    copy(spelling);
    out += spelling.size;
    column += spelling.size;
  };
  for (std::size_t i = begin; i < padded_end; ++i) {
    spell(i, [&](const Spelling& spelling) { std::memcpy(out, spelling.chars.data(), 4); });
  }
  for (std::size_t i = padded_end; i < end; ++i) {
    spell(i, [&](const Spelling& spelling) {
      std::memcpy(out, spelling.chars.data(), spelling.size);
    });
  }
}

void ByteText::appendTo(std::string& out, unsigned threads) const {
  const Style& s = styleOf(style_);
  const std::size_t at = out.size();
  out.resize(at + size_);
  char* text = out.data() + at;
  std::memcpy(text, s.start.data(), s.start.size());
  parallelFor(threads, checkpoints_.size(),
              [&](std::size_t piece, unsigned) { writePiece(piece, text); });
  std::memcpy(text + size_ - s.end.size(), s.end.data(), s.end.size());
}

}  // namespace octopoint::prepare
