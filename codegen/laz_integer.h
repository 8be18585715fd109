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

  // Decodes the value predicted as `prediction`.
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

}  // namespace octopoint::laz
