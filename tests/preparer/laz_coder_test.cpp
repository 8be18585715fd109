// LAZ's arithmetic coder and integer compressor (codegen/laz_arithmetic.h, codegen/laz_integer.h):
// what the encoder writes the decoder reads back, for bits, symbols of every alphabet size, raw
// values of every width and integers at the edges of their range, in long mixed streams that make
// the models adapt, halve their counts and carry; and the decoder reads exactly the bytes written.

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <variant>
#include <vector>

#include "codegen/laz_arithmetic.h"
#include "codegen/laz_integer.h"

namespace octopoint::laz {
namespace {

// One coded value: which kind, its parameter (alphabet, width or context) and the value.
struct CoderStep {
  int kind;  // 0 bit, 1 symbol, 2 raw bits, 3 integer
  std::uint32_t parameter;
  std::int64_t value;
};

constexpr std::uint32_t kAlphabets[] = {2, 3, 6, 16, 17, 64, 256, 516, 2048};
constexpr int kIntegerWidths[] = {8, 16, 32};

std::vector<CoderStep> mixedSteps(std::uint32_t seed, std::size_t count) {
  std::mt19937 random(seed);
  std::vector<CoderStep> steps;
  for (std::size_t i = 0; i < count; ++i) {
    const int kind = static_cast<int>(random() % 4);
    // Skewed values most of the time, so that the models sharpen and a surprise costs many bits.
    const bool typical = random() % 16 != 0;
    switch (kind) {
      case 0:
        steps.push_back({0, 0, typical ? 0 : 1});
        break;
      case 1: {
        const std::uint32_t symbols = kAlphabets[random() % std::size(kAlphabets)];
        steps.push_back(
            {1, symbols, static_cast<std::int64_t>(typical ? 1 % symbols : random() % symbols)});
        break;
      }
      case 2: {
        const std::uint32_t bits = 1 + random() % 32;
        const std::uint64_t mask = (std::uint64_t{1} << bits) - 1;
        steps.push_back({2, bits, static_cast<std::int64_t>(random() & mask)});
        break;
      }
      default: {
        const auto width_index = random() % std::size(kIntegerWidths);
        const int bits = kIntegerWidths[width_index];
        std::int64_t value;
        if (!typical) {
          value = bits == 32 ? (random() % 2 ? std::numeric_limits<std::int32_t>::min()
                                             : std::numeric_limits<std::int32_t>::max())
                             : (random() % 2 ? 0 : (std::int64_t{1} << bits) - 1);
        } else {
          value = bits == 32 ? static_cast<std::int32_t>(random())
                             : static_cast<std::int64_t>(random() % (1u << bits));
        }
        steps.push_back({3, static_cast<std::uint32_t>(width_index), value});
        break;
      }
    }
  }
  return steps;
}

// The models of one side of the coder: a bit model, a symbol model per alphabet, an integer
// compressor per width (4 contexts, the previous value as the prediction).
struct CoderModels {
  explicit CoderModels(bool decoding) {
    for (std::uint32_t symbols : kAlphabets) symbols_.emplace_back(symbols, decoding);
    for (int bits : kIntegerWidths) integers_.emplace_back(bits, 4, decoding);
    for (auto& integers : integers_) integers.reset();
  }
  SymbolModel& symbolModel(std::uint32_t symbols) {
    for (std::size_t i = 0; i < std::size(kAlphabets); ++i)
      if (kAlphabets[i] == symbols) return symbols_[i];
    return symbols_[0];
  }
  BitModel bit;
  std::vector<SymbolModel> symbols_;
  std::vector<IntegerModels> integers_;
  std::array<std::int32_t, 3> previous{};
};

std::vector<std::uint8_t> encodeSteps(const std::vector<CoderStep>& steps) {
  std::vector<std::uint8_t> bytes;
  ArithmeticEncoder encoder(bytes);
  encoder.start();
  CoderModels models(false);
  for (const CoderStep& step : steps) {
    switch (step.kind) {
      case 0:
        encoder.encodeBit(models.bit, static_cast<std::uint32_t>(step.value));
        break;
      case 1:
        encoder.encodeSymbol(models.symbolModel(step.parameter),
                             static_cast<std::uint32_t>(step.value));
        break;
      case 2:
        encoder.writeBits(static_cast<int>(step.parameter), static_cast<std::uint32_t>(step.value));
        break;
      default: {
        const auto value = static_cast<std::int32_t>(step.value);
        models.integers_[step.parameter].encode(encoder, models.previous[step.parameter], value,
                                                static_cast<std::uint32_t>(step.value & 3));
        models.previous[step.parameter] = value;
      }
    }
  }
  encoder.finish();
  return bytes;
}

// Decodes `steps` from `bytes`; returns the index of the first step that differs, or steps.size().
std::size_t firstMismatch(const std::vector<CoderStep>& steps,
                          const std::vector<std::uint8_t>& bytes, std::uint64_t* overrun) {
  MemoryInput input(bytes);
  ArithmeticDecoder decoder;
  decoder.attach(input);
  decoder.start();
  CoderModels models(true);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const CoderStep& step = steps[i];
    std::int64_t got = 0;
    switch (step.kind) {
      case 0:
        got = decoder.decodeBit(models.bit);
        break;
      case 1:
        got = decoder.decodeSymbol(models.symbolModel(step.parameter));
        break;
      case 2:
        got = decoder.readBits(static_cast<int>(step.parameter));
        break;
      default: {
        // The context is the value's low bits: known to the decoder only through the test.
        got = models.integers_[step.parameter].decode(decoder, models.previous[step.parameter],
                                                      static_cast<std::uint32_t>(step.value & 3));
        models.previous[step.parameter] = static_cast<std::int32_t>(got);
        if (kIntegerWidths[step.parameter] < 32)
          got &= (std::int64_t{1} << kIntegerWidths[step.parameter]) - 1;
      }
    }
    if (got != step.value) return i;
  }
  *overrun = decoder.overrun();
  return steps.size();
}

TEST(LazCoder, EveryKindOfValueDecodesAsEncodedInLongMixedStreams) {
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    const std::vector<CoderStep> steps = mixedSteps(seed, 20000);
    const std::vector<std::uint8_t> bytes = encodeSteps(steps);
    std::uint64_t overrun = 0;
    ASSERT_EQ(firstMismatch(steps, bytes, &overrun), steps.size()) << "seed " << seed;
    EXPECT_EQ(overrun, 0u) << "the decoder read past the bytes the encoder wrote, seed " << seed;
  }
}

TEST(LazCoder, AWrongByteChangesWhatIsDecoded) {
  const std::vector<CoderStep> steps = mixedSteps(7, 5000);
  std::vector<std::uint8_t> bytes = encodeSteps(steps);
  bytes[bytes.size() / 2] ^= 0x10;
  std::uint64_t overrun = 0;
  EXPECT_LT(firstMismatch(steps, bytes, &overrun), steps.size());
}

TEST(LazCoder, IntegersWrapInTheirWidth) {
  // 16-bit values predicted across the wrap: 65535 after 0 is a corrector of -1, not 65535.
  std::vector<std::uint8_t> bytes;
  ArithmeticEncoder encoder(bytes);
  encoder.start();
  IntegerModels out(16, 1, false), in(16, 1);
  out.reset();
  in.reset();
  const std::vector<std::int32_t> values = {0, 65535, 1, 32768, 32767, 0, 40000};
  std::int32_t previous = 0;
  for (std::int32_t v : values) {
    out.encode(encoder, previous, v, 0);
    previous = v;
  }
  encoder.finish();
  EXPECT_LT(bytes.size(), 24u);  // small correctors: a few bits each
  MemoryInput input(bytes);
  ArithmeticDecoder decoder;
  decoder.attach(input);
  decoder.start();
  previous = 0;
  for (std::int32_t v : values) {
    previous = in.decode(decoder, previous, 0);
    EXPECT_EQ(previous, v);
  }
}

}  // namespace
}  // namespace octopoint::laz
