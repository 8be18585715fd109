// LAZ's integer compressor (codegen/laz_integer.h). Values wrap in their width: all arithmetic on
// them is done in uint32 so that it wraps as the format wants without signed overflow.

#include "codegen/laz_integer.h"

#include <algorithm>

namespace octopoint::laz {

IntegerModels::IntegerModels(int bits, std::uint32_t contexts, bool for_decoding)
    : corrector_range_(bits < 32 ? 1u << bits : 0),
      corrector_min_(bits < 32 ? -static_cast<std::int32_t>(corrector_range_ / 2) : INT32_MIN),
      corrector_max_(bits < 32 ? static_cast<std::int32_t>(corrector_range_ / 2 - 1) : INT32_MAX) {
  k_models_.reserve(contexts);
  for (std::uint32_t i = 0; i < contexts; ++i)
    k_models_.emplace_back(static_cast<std::uint32_t>(bits + 1), for_decoding);
  corrector_.reserve(static_cast<std::size_t>(bits));
  for (int k = 1; k <= bits; ++k)
    corrector_.emplace_back(1u << std::min(k, kHighBits), for_decoding);
}

void IntegerModels::reset() {
  for (SymbolModel& model : k_models_) model.reset();
  zero_or_one_.reset();
  for (SymbolModel& model : corrector_) model.reset();
  k_ = 0;
}

void IntegerModels::encode(ArithmeticEncoder& encoder, std::int32_t prediction, std::int32_t value,
                           std::uint32_t context) {
  std::int32_t corrector = static_cast<std::int32_t>(static_cast<std::uint32_t>(value) -
                                                     static_cast<std::uint32_t>(prediction));
  if (corrector_range_ != 0) {  // into [corrector_min, corrector_max]
    if (corrector < corrector_min_) {
      corrector += static_cast<std::int32_t>(corrector_range_);
    } else if (corrector > corrector_max_) {
      corrector -= static_cast<std::int32_t>(corrector_range_);
    }
  }
  // The smallest k with corrector in [-(2^k - 1), 2^k].
  std::uint32_t magnitude = corrector <= 0 ? 0u - static_cast<std::uint32_t>(corrector)
                                           : static_cast<std::uint32_t>(corrector) - 1;
  k_ = 0;
  while (magnitude) {
    magnitude >>= 1;
    ++k_;
  }
  encoder.encodeSymbol(k_models_[context], k_);
  if (k_ == 0) {
    encoder.encodeBit(zero_or_one_, static_cast<std::uint32_t>(corrector));
    return;
  }
  if (k_ >= 32) return;
  std::uint32_t c = corrector < 0 ? static_cast<std::uint32_t>(corrector) + ((1u << k_) - 1)
                                  : static_cast<std::uint32_t>(corrector) - 1;
  SymbolModel& model = corrector_[k_ - 1];
  if (k_ <= kHighBits) {
    encoder.encodeSymbol(model, c);
  } else {
    const int low_bits = static_cast<int>(k_) - kHighBits;
    encoder.encodeSymbol(model, c >> low_bits);
    encoder.writeBits(low_bits, c & ((1u << low_bits) - 1));
  }
}

}  // namespace octopoint::laz
