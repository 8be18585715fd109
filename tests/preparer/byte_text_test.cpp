// ByteText against the byte-at-a-time spelling it replaced (kept here as the oracle): the same
// text for any bytes, any length (pieces of 1 MiB written by different threads), either style.
#include "codegen/byte_text.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace octopoint::prepare {
namespace {

std::string oracleBytes(const std::vector<std::uint8_t>& bytes) {
  std::string text = "    ";
  std::size_t column = 0;
  for (std::uint8_t byte : bytes) {
    char item[5];
    const int size = std::snprintf(item, sizeof item, "%u,", static_cast<unsigned>(byte));
    if (column + static_cast<std::size_t>(size) > kLineWidth) {
      text += "\n    ";
      column = 0;
    }
    text.append(item, static_cast<std::size_t>(size));
    column += static_cast<std::size_t>(size);
  }
  return text + "\n";
}

std::string oracleStrings(const std::vector<std::uint8_t>& bytes) {
  std::string text = "    \"";
  std::size_t column = 0;
  for (std::uint8_t byte : bytes) {
    const bool plain = byte >= 0x20 && byte < 0x7f && byte != '"' && byte != '\\' && byte != '?';
    const std::size_t size = plain ? 1 : 4;
    if (column + size > kLineWidth) {
      text += "\"\n    \"";
      column = 0;
    }
    if (plain) {
      text += static_cast<char>(byte);
    } else {
      text += '\\';
      text += static_cast<char>('0' + (byte >> 6));
      text += static_cast<char>('0' + ((byte >> 3) & 7));
      text += static_cast<char>('0' + (byte & 7));
    }
    column += size;
  }
  return text + "\"\n";
}

std::string spelled(const std::vector<std::uint8_t>& bytes, EmitStyle style, unsigned threads) {
  std::string text = "head";
  const ByteText byte_text(bytes, style);
  byte_text.appendTo(text, threads);
  EXPECT_EQ(text.size(), 4 + byte_text.size());
  return text.substr(4);
}

// Compared with == rather than EXPECT_EQ: a difference in megabytes of text is not printed whole.
void expectOracle(const std::vector<std::uint8_t>& bytes) {
  const std::string as_bytes = oracleBytes(bytes);
  const std::string as_strings = oracleStrings(bytes);
  for (unsigned threads : {1u, 2u, 3u}) {
    EXPECT_TRUE(spelled(bytes, EmitStyle::kBytes, threads) == as_bytes) << bytes.size() << " bytes";
    EXPECT_TRUE(spelled(bytes, EmitStyle::kStrings, threads) == as_strings)
        << bytes.size() << " bytes";
  }
}

TEST(ByteText, ShortArraysAsTheOracle) {
  for (std::size_t n = 0; n < 300; ++n) {
    std::vector<std::uint8_t> bytes(n);
    for (std::size_t i = 0; i < n; ++i) bytes[i] = static_cast<std::uint8_t>(i * 37 + n);
    expectOracle(bytes);
  }
}

TEST(ByteText, PiecesOnThreadsAsTheOracle) {
  // Lengths around the 1 MiB pieces, random bytes (mixing every spelling length), and runs of
  // plain or of escaped bytes only, so that a piece can end on either kind.
  std::mt19937 random(15);
  std::vector<std::uint8_t> bytes((std::size_t{5} << 19) + 3);
  for (std::uint8_t& b : bytes) b = static_cast<std::uint8_t>(random());
  expectOracle(bytes);
  bytes.resize((std::size_t{1} << 20) + 1);
  std::fill(bytes.end() - 5, bytes.end(), std::uint8_t{'a'});
  expectOracle(bytes);
  std::fill(bytes.begin(), bytes.end(), std::uint8_t{200});
  expectOracle(bytes);
}

}  // namespace
}  // namespace octopoint::prepare
