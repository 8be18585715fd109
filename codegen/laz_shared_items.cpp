// The colour and wave-packet coding LAZ's point-wise and layered items share
// (codegen/laz_shared_items.h).

#include "codegen/laz_shared_items.h"

#include <array>
#include <cstring>

#include "codegen/laz_predictors.h"

namespace octopoint::laz {

void RgbModels::reset() {
  used.reset();
  for (SymbolModel& model : diff) model.reset();
}

// Which of the six colour bytes changed, then each changed byte as a difference, green and blue
// predicted from red's change (the channels of a colour tend to move together).
void decodeRgb(ArithmeticDecoder& shared, RgbModels& models, const std::uint8_t* last_bytes,
               std::uint8_t* out) {
  ArithmeticDecoder d = shared;  // in registers for the colour (codegen/laz_arithmetic.h)
  std::array<std::uint16_t, 3> last{};
  for (std::size_t c = 0; c < 3; ++c) last[c] = load<std::uint16_t>(last_bytes + 2 * c);
  const auto symbol = [&](std::size_t byte) {
    return static_cast<std::int32_t>(d.decodeSymbol(models.diff[byte]));
  };
  const std::uint32_t used = d.decodeSymbol(models.used);
  std::array<std::uint32_t, 3> rgb{};
  const auto lo = [](std::uint32_t v) { return static_cast<std::int32_t>(v & 0xff); };
  const auto hi = [](std::uint32_t v) { return static_cast<std::int32_t>(v >> 8); };
  rgb[0] = (used & 1) ? foldByte(symbol(0) + lo(last[0])) : lo(last[0]);
  rgb[0] |= (used & 2) ? std::uint32_t{foldByte(symbol(1) + hi(last[0]))} << 8 : last[0] & 0xff00u;
  if (used & 64) {
    std::int32_t diff = lo(rgb[0]) - lo(last[0]);
    rgb[1] = (used & 4) ? foldByte(symbol(2) + clampByte(diff + lo(last[1]))) : lo(last[1]);
    if (used & 16) {
      diff = (diff + (lo(rgb[1]) - lo(last[1]))) / 2;
      rgb[2] = foldByte(symbol(4) + clampByte(diff + lo(last[2])));
    } else {
      rgb[2] = lo(last[2]);
    }
    diff = hi(rgb[0]) - hi(last[0]);
    rgb[1] |= (used & 8) ? std::uint32_t{foldByte(symbol(3) + clampByte(diff + hi(last[1])))} << 8
                         : last[1] & 0xff00u;
    if (used & 32) {
      diff = (diff + (hi(rgb[1]) - hi(last[1]))) / 2;
      rgb[2] |= std::uint32_t{foldByte(symbol(5) + clampByte(diff + hi(last[2])))} << 8;
    } else {
      rgb[2] |= last[2] & 0xff00u;
    }
  } else {  // a grey: all three channels alike
    rgb[1] = rgb[2] = rgb[0];
  }
  for (std::size_t c = 0; c < 3; ++c) store(out + 2 * c, static_cast<std::uint16_t>(rgb[c]));
  shared = d;
}

void WavePacketModels::reset() {
  last_diff = 0;
  last_offset_symbol = 0;
  index.reset();
  for (auto& model : offset_kind) model.reset();
  offset_diff.reset();
  size.reset();
  return_point.reset();
  xyz.reset();
}

// The descriptor index, the offset of the waveform (same, following the last packet, a
// difference, or whole), and the packet's size, return point and direction.
void decodeWavePacket(ArithmeticDecoder& shared, WavePacketModels& models, const std::uint8_t* last,
                      std::uint8_t* out) {
  ArithmeticDecoder d = shared;  // in registers for the packet (codegen/laz_arithmetic.h)
  std::array<std::uint8_t, kWavePacketBytes> next{};
  next[0] = static_cast<std::uint8_t>(d.decodeSymbol(models.index));
  std::uint64_t offset = load<std::uint64_t>(last + 1);
  const std::uint32_t last_size = load<std::uint32_t>(last + 9);
  models.last_offset_symbol = d.decodeSymbol(models.offset_kind[models.last_offset_symbol]);
  if (models.last_offset_symbol == 1) {
    offset += last_size;
  } else if (models.last_offset_symbol == 2) {
    models.last_diff = models.offset_diff.decode(d, models.last_diff, 0);
    offset += static_cast<std::uint64_t>(std::int64_t{models.last_diff});
  } else if (models.last_offset_symbol == 3) {
    const std::uint64_t low = d.readInt();
    offset = (std::uint64_t{d.readInt()} << 32) | low;
  }
  store(next.data() + 1, offset);
  store(next.data() + 9, models.size.decode(d, static_cast<std::int32_t>(last_size), 0));
  store(next.data() + 13, models.return_point.decode(d, load<std::int32_t>(last + 13), 0));
  for (std::uint32_t axis = 0; axis < 3; ++axis) {
    const std::size_t at = 17 + 4 * axis;
    store(next.data() + at, models.xyz.decode(d, load<std::int32_t>(last + at), axis));
  }
  std::memcpy(out, next.data(), next.size());
  shared = d;
}

}  // namespace octopoint::laz
