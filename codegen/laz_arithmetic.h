#pragma once
// The adaptive arithmetic coder of LAZ (the LASzip compression), written from its published
// description: a 32-bit range coder after Amir Said ("Introduction to Arithmetic Coding",
// HPL-2004-76) with adaptive models whose counts are refreshed at growing intervals. A LAZ decoder
// must reproduce the encoder's every rounding, so each constant below is part of the format:
//
//  - the interval is [base, base + length) with length kept in [2^24, 2^32): it is renormalised a
//    byte at a time (shifted left 8) whenever it drops below 2^24;
//  - a bit model holds P(0) in Q13 (length >> 13 times it splits the interval); a symbol model
//  holds
//    a cumulative distribution in Q15 (length >> 15 times it);
//  - models recompute their probabilities after update_cycle symbols, the cycle growing by 5/4 up
//  to
//    a cap, and halve their counts past 2^13 (bits) or 2^15 (symbols) so that they keep adapting;
//  - raw bits (readBits) split the interval evenly.
//
// The decoder never reads outside its input: past the end it reads zero bytes and counts them
// (overrun()), and a raw value out of range marks it failed(): the caller checks both at the end of
// a chunk and refuses the chunk, so that a corrupt stream costs its own length and no more.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace octopoint::laz {

inline constexpr std::uint32_t kMinLength = 1u << 24;  // below it the interval is renormalised
inline constexpr std::uint32_t kMaxLength = 0xffffffffu;
inline constexpr int kBitModelShift = 13;     // bit probabilities are Q13
inline constexpr int kSymbolModelShift = 15;  // symbol distributions are Q15

// An adaptive model of one bit.
class BitModel {
 public:
  BitModel() { reset(); }
  void reset();
  void update();

  std::uint32_t probability_0 = 0;  // Q13
  std::uint32_t count_0 = 0;
  std::uint32_t count = 0;
  std::uint32_t until_update = 0;
  std::uint32_t cycle = 0;
};

// An adaptive model of `symbols` symbols (2 to 2048). A decoder's model also keeps a lookup table
// that finds the symbol of a Q15 quantile in one step almost always: the table has at least twice
// as many entries as the model has symbols, so that most entries lie inside one symbol's interval
// and the rest name the first of the few symbols they cover (the decoder steps up from it).
// LASzip's decoder tables have a quarter to a half as many entries as symbols (and none below 17
// symbols) and bisect the rest, a branch the processor cannot predict at every step; which symbol
// is found is the same either way, so the format does not care.
class SymbolModel {
 public:
  // A decoder table entry: the symbol at the entry's quantile and the bounds (Q15) of its
  // interval and of the next one's, so that a lookup and one step up read one entry and no
  // distribution (each load waits for the one before: they are most of a symbol's time). Past the
  // last symbol a bound is 0xffff, above every quantile.
  struct Entry {
    std::uint16_t symbol;
    std::uint16_t low;   // distribution[symbol]
    std::uint16_t high;  // distribution[symbol + 1]
    std::uint16_t next;  // distribution[symbol + 2]
  };

  explicit SymbolModel(std::uint32_t symbols, bool for_decoding = true);
  // A model that has coded nothing since its last reset is left as it is: most of a chunk's models
  // (the integer compressor's wide correctors) never code a symbol, and a reset costs a table.
  void reset();
  void update();
  std::uint32_t symbols() const { return symbols_; }

  // Q15 cumulative: distribution[s] = P(< s); distribution[symbols] and distribution[symbols + 1]
  // are kPastLastSymbol, so that a decoder's upward step stops at the last symbol without a test
  // of its own. 16 bits are enough for both: a distribution is at most 2^15, and a count at most
  // 2^15 + (2048 + 6) * 8 (the counts are halved when their sum passes 2^15 at an update, and an
  // update comes after at most (symbols + 6) * 8 symbols).
  std::vector<std::uint16_t> distribution;
  std::vector<std::uint16_t> counts;
  // Decoder: table[t] is the symbol at Q15 quantile t << table_shift, for every quantile a
  // decoder can meet (kMaxQuantile), so that a lookup needs no bound of its own.
  std::vector<Entry> table;
  std::uint32_t table_shift = 0;
  std::uint32_t until_update = 0;

 private:
  void initialise();
  void writeTable();

  std::uint32_t symbols_;
  std::uint32_t total_ = 0;
  std::uint32_t cycle_ = 0;
};

inline constexpr std::uint16_t kPastLastSymbol = 0xffff;  // above every quantile (kMaxQuantile)

// Where a decoder takes its bytes from: windows handed out one after another, empty at the end.
class ByteInput {
 public:
  virtual ~ByteInput() = default;
  virtual std::span<const std::uint8_t> more() = 0;
};

// Bytes already in memory.
class MemoryInput final : public ByteInput {
 public:
  explicit MemoryInput(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  void assign(std::span<const std::uint8_t> bytes) { bytes_ = bytes; }
  std::span<const std::uint8_t> more() override {
    const auto out = bytes_;
    bytes_ = {};
    return out;
  }

 private:
  std::span<const std::uint8_t> bytes_;
};

// The quantile of the code value in its interval, value / (length >> 15), is below 2^15 + 64:
// the decoder keeps value < length (start() makes it so, and every step keeps it), and
// length >> 15 is at least 2^9, so value / (length >> 15) < 2^15 + 2^15 / 2^9.
inline constexpr std::uint32_t kMaxQuantile = (1u << kSymbolModelShift) + 63;

// A decoder is a value: an item decoder copies it into a local variable for a point's fields and
// back after them, so that the code value, the interval and the input cursor stay in registers
// (the record bytes it stores could otherwise be the decoder's, as far as the compiler knows). For
// that, nothing on the decoding path takes the decoder's address: the input is refilled through
// a static function.
class ArithmeticDecoder {
 public:
  // Reads from `input` from now on; raw bytes may be taken (rawByte) before start().
  void attach(ByteInput& input);
  // Starts the arithmetic code: reads its first four bytes.
  void start();
  // decodeBit, decodeSymbol and readBits are inline (below): they are most of a point's decoding.
  std::uint32_t decodeBit(BitModel& model);
  std::uint32_t decodeSymbol(SymbolModel& model);
  std::uint32_t readBits(int bits);  // 1 to 32 raw bits
  std::uint32_t readInt() { return readBits(32); }
  // Zero bytes read past the end of the input; a valid stream needs none.
  std::uint64_t overrun() const { return overrun_; }
  // Bytes of the last window handed over but not read yet.
  std::size_t unread() const { return static_cast<std::size_t>(end_ - next_); }
  bool failed() const { return failed_; }
  // A byte outside the arithmetic code (a chunk's first point is stored raw): only before start().
  std::uint8_t rawByte() { return nextByte(); }

 private:
  static std::span<const std::uint8_t> nextWindow(ByteInput* input);
  __attribute__((always_inline)) std::uint8_t nextByte() {
    if (next_ == end_) [[unlikely]] {
      const std::span<const std::uint8_t> window = nextWindow(input_);
      if (window.empty()) {
        ++overrun_;
        return 0;
      }
      next_ = window.data();
      end_ = next_ + window.size();
    }
    return *next_++;
  }
  // The interval is at least 1 wide after every step (a symbol's at least 2^9, a bit's at least
  // 1, raw bits' at least 2^5), so a renormalisation takes at most three bytes.
  __attribute__((always_inline)) void renormalise() {
    if (end_ - next_ >= 3) [[likely]] {  // no test for each byte
      do {
        value_ = (value_ << 8) | *next_++;
        length_ <<= 8;
      } while (length_ < kMinLength);
      return;
    }
    do {
      value_ = (value_ << 8) | nextByte();
      length_ <<= 8;
    } while (length_ < kMinLength);
  }
  std::uint32_t readNarrowBits(int bits);  // 1 to 19

  std::uint32_t value_ = 0;
  std::uint32_t length_ = kMaxLength;
  const std::uint8_t* next_ = nullptr;
  const std::uint8_t* end_ = nullptr;
  ByteInput* input_ = nullptr;
  std::uint64_t overrun_ = 0;
  bool failed_ = false;
};

__attribute__((always_inline)) inline std::uint32_t ArithmeticDecoder::decodeBit(BitModel& model) {
  const std::uint32_t split = model.probability_0 * (length_ >> kBitModelShift);
  const std::uint32_t bit = value_ >= split;
  if (bit == 0) {
    length_ = split;
    ++model.count_0;
  } else {
    value_ -= split;
    length_ -= split;
  }
  if (length_ < kMinLength) renormalise();
  if (--model.until_update == 0) model.update();
  return bit;
}

__attribute__((always_inline)) inline std::uint32_t ArithmeticDecoder::decodeSymbol(
    SymbolModel& model) {
  const std::uint32_t whole = length_;
  length_ >>= kSymbolModelShift;
  // The value as a Q15 quantile of the interval: distribution[s] * length_ <= value_ exactly when
  // distribution[s] <= quantile, so the symbol is the last s with distribution[s] <= quantile.
  // The quantile is at most kMaxQuantile, which the table covers.
  const std::uint32_t quantile = value_ / length_;
  const SymbolModel::Entry entry = model.table[quantile >> model.table_shift];
  // The entry spans symbols: one step up is common enough to be taken without a branch, more rare.
  const bool up = entry.high <= quantile;
  std::uint32_t symbol = entry.symbol + static_cast<std::uint32_t>(up);
  std::uint32_t bottom = up ? entry.high : entry.low;
  std::uint32_t top = up ? entry.next : entry.high;
  if (top <= quantile) [[unlikely]] {
    do {
      ++symbol;
      bottom = top;
      top = model.distribution[symbol + 1];
    } while (top <= quantile);
  }
  const std::uint32_t low = bottom * length_;
  // The last symbol takes the rest of the interval, up to its end.
  const std::uint32_t high = symbol + 1 == model.symbols() ? whole : top * length_;
  value_ -= low;
  length_ = high - low;
  if (length_ < kMinLength) renormalise();
  ++model.counts[symbol];
  if (--model.until_update == 0) model.update();
  return symbol;
}

__attribute__((always_inline)) inline std::uint32_t ArithmeticDecoder::readNarrowBits(int bits) {
  length_ >>= bits;
  std::uint32_t value = value_ / length_;
  value_ -= length_ * value;
  if (length_ < kMinLength) renormalise();
  if (value >> bits) [[unlikely]] {  // only a corrupt stream gets here
    failed_ = true;
    value &= (1u << bits) - 1;
  }
  return value;
}

__attribute__((always_inline)) inline std::uint32_t ArithmeticDecoder::readBits(int bits) {
  if (bits <= 19) return readNarrowBits(bits);
  // Wider values come as a low 16-bit half and the rest.
  const std::uint32_t low = readNarrowBits(16);
  return (readNarrowBits(bits - 16) << 16) | low;
}

// The encoder: the exact inverse of ArithmeticDecoder, writing to a byte vector.
class ArithmeticEncoder {
 public:
  explicit ArithmeticEncoder(std::vector<std::uint8_t>& out) : out_(out) {}
  void start();
  void encodeBit(BitModel& model, std::uint32_t bit);
  void encodeSymbol(SymbolModel& model, std::uint32_t symbol);
  void writeBits(int bits, std::uint32_t value);
  void writeInt(std::uint32_t value) { writeBits(32, value); }
  // Flushes the interval so that a decoder reads exactly the bytes written, no more.
  void finish();

 private:
  void carry();
  void renormalise();

  std::vector<std::uint8_t>& out_;
  std::size_t start_ = 0;  // where this stream's bytes begin in out_
  std::uint32_t base_ = 0;
  std::uint32_t length_ = kMaxLength;
};

}  // namespace octopoint::laz
