// The LAZ arithmetic coder and its models (codegen/laz_arithmetic.h).

#include "codegen/laz_arithmetic.h"

#include <algorithm>
#include <bit>

namespace octopoint::laz {
namespace {

constexpr std::uint32_t kBitModelMaxCount = 1u << kBitModelShift;
constexpr std::uint32_t kSymbolModelMaxCount = 1u << kSymbolModelShift;
constexpr std::uint32_t kBitModelMaxCycle = 64;
constexpr std::uint32_t kMaxSymbols = 1u << 11;

}  // namespace

void BitModel::reset() {
  count_0 = 1;
  count = 2;
  probability_0 = 1u << (kBitModelShift - 1);
  cycle = until_update = 4;  // adapt fast at first
}

void BitModel::update() {
  count += cycle;
  if (count > kBitModelMaxCount) {  // halve, so that the model keeps following the data
    count = (count + 1) >> 1;
    count_0 = (count_0 + 1) >> 1;
    if (count_0 == count) ++count;
  }
  const std::uint32_t scale = 0x80000000u / count;             // Q31 / count
  probability_0 = (count_0 * scale) >> (31 - kBitModelShift);  // Q13
  cycle = std::min((5 * cycle) >> 2, kBitModelMaxCycle);
  until_update = cycle;
}

SymbolModel::SymbolModel(std::uint32_t symbols, bool for_decoding)
    : symbols_(std::clamp(symbols, 2u, kMaxSymbols)) {
  distribution.resize(symbols_ + 2);
  distribution[symbols_] = distribution[symbols_ + 1] = kPastLastSymbol;
  counts.resize(symbols_);
  if (for_decoding) {
    // At least twice as many entries as symbols (2^12 for 2048 symbols: Q15 quantiles >> 3), and
    // the few past 2^15 that a quantile may reach (kMaxQuantile).
    const int table_bits = std::bit_width(symbols_ - 1) + 1;
    table_shift = static_cast<std::uint32_t>(kSymbolModelShift - table_bits);
    table.resize((kMaxQuantile >> table_shift) + 1);
  }
  initialise();
}

void SymbolModel::reset() {
  // Untouched since its reset: its cycle is still the first and not a symbol of it has passed (a
  // cycle only grows, so no later state looks like this).
  if (until_update == cycle_ && cycle_ == (symbols_ + 6) >> 1) return;
  initialise();
}

void SymbolModel::initialise() {
  total_ = 0;
  cycle_ = symbols_;
  std::fill(counts.begin(), counts.end(), std::uint16_t{1});
  update();
  until_update = cycle_ = (symbols_ + 6) >> 1;
}

void SymbolModel::update() {
  total_ += cycle_;
  if (total_ > kSymbolModelMaxCount) {  // halve, so that the model keeps following the data
    total_ = 0;
    for (std::uint16_t& count : counts) {
      count = static_cast<std::uint16_t>((count + 1) >> 1);
      total_ += count;
    }
  }
  const std::uint32_t scale = 0x80000000u / total_;  // Q31 / total
  const std::uint32_t symbols = symbols_;
  std::uint16_t* out = distribution.data();
  const std::uint16_t* in = counts.data();
  std::uint32_t sum = 0;
  for (std::uint32_t s = 0; s < symbols; ++s) {
    out[s] = static_cast<std::uint16_t>((scale * sum) >> (31 - kSymbolModelShift));  // Q15, <= 2^15
    sum += in[s];
  }
  if (!table.empty()) writeTable();
  cycle_ = std::min((5 * cycle_) >> 2, (symbols + 6) << 3);
  until_update = cycle_;
}

void SymbolModel::writeTable() {
  // Entry t names the symbol whose interval holds quantile t << shift: the last symbol s whose
  // distribution[s] is at most it. Each symbol's first entry is the first at or above its
  // distribution; the entries before it, from the symbol before's first on, are the symbol
  // before's (a symbol of no width has none).
  const std::uint16_t* at = distribution.data();
  const std::uint32_t symbols = symbols_;
  const std::uint32_t shift = table_shift;
  const std::uint32_t round_up = (1u << shift) - 1;
  const auto size = static_cast<std::uint32_t>(table.size());
  Entry* entries = table.data();
  std::uint32_t entry = 0;  // the first entry not written yet
  for (std::uint32_t s = 1; s <= symbols; ++s) {
    // within the table: a distribution is at most 2^15, and 2^15 >> shift < size
    const std::uint32_t first = s < symbols ? (at[s] + round_up) >> shift : size;
    if (entry < first) {
      // the bounds past the last symbol are kPastLastSymbol
      const Entry below{static_cast<std::uint16_t>(s - 1), at[s - 1], at[s], at[s + 1]};
      do {
        entries[entry] = below;
      } while (++entry < first);
    }
  }
}

void ArithmeticDecoder::attach(ByteInput& input) {
  input_ = &input;
  next_ = end_ = nullptr;
  overrun_ = 0;
  failed_ = false;
}

void ArithmeticDecoder::start() {
  length_ = kMaxLength;
  value_ = 0;
  for (int i = 0; i < 4; ++i) value_ = (value_ << 8) | nextByte();
  // An encoder's code starts below 2^32 - 1: a value at the top is a corrupt stream. It is kept
  // below the interval's end, as decodeSymbol's table lookup needs (kMaxQuantile).
  if (value_ >= length_) {
    failed_ = true;
    value_ = length_ - 1;
  }
}

std::span<const std::uint8_t> ArithmeticDecoder::nextWindow(ByteInput* input) {
  return input ? input->more() : std::span<const std::uint8_t>{};
}

void ArithmeticEncoder::start() {
  start_ = out_.size();
  base_ = 0;
  length_ = kMaxLength;
}

void ArithmeticEncoder::carry() {
  std::size_t at = out_.size();
  while (at > start_ && out_[at - 1] == 0xff) out_[--at] = 0;
  if (at > start_) ++out_[at - 1];
}

void ArithmeticEncoder::renormalise() {
  do {
    out_.push_back(static_cast<std::uint8_t>(base_ >> 24));
    base_ <<= 8;
    length_ <<= 8;
  } while (length_ < kMinLength);
}

void ArithmeticEncoder::encodeBit(BitModel& model, std::uint32_t bit) {
  const std::uint32_t split = model.probability_0 * (length_ >> kBitModelShift);
  if (bit == 0) {
    length_ = split;
    ++model.count_0;
  } else {
    const std::uint32_t old_base = base_;
    base_ += split;
    length_ -= split;
    if (old_base > base_) carry();
  }
  if (length_ < kMinLength) renormalise();
  if (--model.until_update == 0) model.update();
}

void ArithmeticEncoder::encodeSymbol(SymbolModel& model, std::uint32_t symbol) {
  const std::uint32_t old_base = base_;
  if (symbol == model.symbols() - 1) {  // the last symbol takes the rest of the interval
    const std::uint32_t low = model.distribution[symbol] * (length_ >> kSymbolModelShift);
    base_ += low;
    length_ -= low;
  } else {
    length_ >>= kSymbolModelShift;
    const std::uint32_t low = model.distribution[symbol] * length_;
    base_ += low;
    length_ = model.distribution[symbol + 1] * length_ - low;
  }
  if (old_base > base_) carry();
  if (length_ < kMinLength) renormalise();
  ++model.counts[symbol];
  if (--model.until_update == 0) model.update();
}

void ArithmeticEncoder::writeBits(int bits, std::uint32_t value) {
  if (bits > 19) {
    writeBits(16, value & 0xffff);
    value >>= 16;
    bits -= 16;
  }
  const std::uint32_t old_base = base_;
  base_ += value * (length_ >>= bits);
  if (old_base > base_) carry();
  if (length_ < kMinLength) renormalise();
}

void ArithmeticEncoder::finish() {
  const std::uint32_t old_base = base_;
  bool another_byte = true;
  if (length_ > 2 * kMinLength) {
    base_ += kMinLength;
    length_ = kMinLength >> 1;
  } else {
    base_ += kMinLength >> 1;
    length_ = kMinLength >> 9;
    another_byte = false;
  }
  if (old_base > base_) carry();
  renormalise();
  // The decoder reads four bytes ahead: these let it end exactly where the stream ends.
  out_.insert(out_.end(), another_byte ? 3 : 2, 0);
}

}  // namespace octopoint::laz
