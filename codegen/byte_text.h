#pragma once
// The bytes of a model's arrays spelled as C++ source text, in either EmitStyle, at the speed of a
// copy: tens of megabytes of text for a large model. A first pass over the bytes finds where the
// lines break (it only adds up lengths); the text is then written straight into its place in the
// output, in pieces on several threads, each piece starting where that pass said it would.
//
// The text, for style kStrings: `    "` then each byte as itself when plainly printable (not '"',
// '\\' or '?') or as a three-digit octal escape, a new piece `"\n    "` whenever the next byte's
// spelling would take the line past kLineWidth characters, and `"\n` at the end. For kBytes: `    `
// then "N," per byte (decimal), "\n    " at the same rule, "\n" at the end.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "codegen/model_writer.h"

namespace octopoint::prepare {

inline constexpr std::size_t kLineWidth = 100;

class ByteText {
 public:
  ByteText(std::span<const std::uint8_t> bytes, EmitStyle style);

  // The length of the whole text.
  std::size_t size() const { return size_; }
  // Writes the text at the end of `out` (which grows by size(); reserve beforehand to avoid a copy)
  // on up to `threads` threads.
  void appendTo(std::string& out, unsigned threads) const;

 private:
  // Where a piece of the bytes starts in the text, and the column there.
  struct Checkpoint {
    std::size_t offset;
    std::size_t column;
  };
  void writePiece(std::size_t piece, char* text) const;

  std::span<const std::uint8_t> bytes_;
  EmitStyle style_;
  std::vector<Checkpoint> checkpoints_;  // one per kPieceBytes of bytes
  std::size_t size_ = 0;
};

}  // namespace octopoint::prepare
