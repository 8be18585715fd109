#pragma once
// LAZ's integer compressor: a value is coded as its difference from a prediction (the corrector),
// folded into the value's width, in two steps: k, the number of bits the corrector needs (a symbol
// in one of `contexts` models, the context chosen by the caller), then the corrector within the
// 2^k values of that width: its top bits (at most 8) through a model per k, the rest raw. k = 0
// means a corrector of 0 or 1, coded as a bit.

#include <cstdint>
#include <vector>

#include "codegen/laz_arithmetic.h"

namespace octopoint::laz {

class IntegerModels {
 public:
  // `bits`: the width of the values (1 to 32), `contexts`: how many k models.
  IntegerModels(int bits, std::uint32_t contexts, bool for_decoding = true);
  void reset();

  // The last value's k (the corrector's bit count), a context for what follows.
  std::uint32_t k() const { return k_; }

  // Decodes the value predicted as `prediction`. Inline (below): the item decoders keep their
  // ArithmeticDecoder in registers through it (codegen/laz_arithmetic.h).
  std::int32_t decode(ArithmeticDecoder& decoder, std::int32_t prediction, std::uint32_t context);
  void encode(ArithmeticEncoder& encoder, std::int32_t prediction, std::int32_t value,
              std::uint32_t context);

 private:
  static constexpr int kHighBits = 8;  // corrector bits coded with a model; the rest are raw

  std::uint32_t corrector_range_;  // 2^bits, 0 for 32 bits (all of uint32 arithmetic)
  std::int32_t corrector_min_;
  std::int32_t corrector_max_;
  std::vector<SymbolModel> k_models_;   // by context
  BitModel zero_or_one_;                // k = 0
  std::vector<SymbolModel> corrector_;  // by k - 1
  std::uint32_t k_ = 0;
};

__attribute__((always_inline)) inline std::int32_t IntegerModels::decode(ArithmeticDecoder& decoder,
                                                                         std::int32_t prediction,
                                                                         std::uint32_t context) {
  k_ = decoder.decodeSymbol(k_models_[context]);
  std::uint32_t corrector;  // two's complement
  if (k_ == 0) {
    corrector = decoder.decodeBit(zero_or_one_);
  } else if (k_ < 32) {
    SymbolModel& model = corrector_[k_ - 1];
    std::uint32_t c;
    if (k_ <= kHighBits) {
      c = decoder.decodeSymbol(model);
    } else {
      const int low_bits = static_cast<int>(k_) - kHighBits;
      c = decoder.decodeSymbol(model) << low_bits;
      c |= decoder.readBits(low_bits);
    }
    // c in [0, 2^(k-1)) stands for [-(2^k - 1), -2^(k-1)], c in [2^(k-1), 2^k) for [2^(k-1)+1,
    // 2^k]: c + 1, less 2^k below the half (without a branch: the sign is a coin toss).
    const std::uint32_t half = 1u << (k_ - 1);
    corrector = c + 1 - ((half << 1) & (0u - static_cast<std::uint32_t>(c < half)));
  } else {
    corrector = static_cast<std::uint32_t>(corrector_min_);
  }
  std::uint32_t value = static_cast<std::uint32_t>(prediction) + corrector;
  if (corrector_range_ != 0) {  // fold into [0, range) as the encoder unfolded it
    if (static_cast<std::int32_t>(value) < 0) {
      value += corrector_range_;
    } else if (value >= corrector_range_) {
      value -= corrector_range_;
    }
  }
  return static_cast<std::int32_t>(value);
}

}  // namespace octopoint::laz
