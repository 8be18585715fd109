// The colour coding the tests' point-wise and layered LAZ encoders share
// (tests/support/laz_shared_encoders.h).

#include "tests/support/laz_shared_encoders.h"

namespace octopoint::laz {

void encodeRgb(ArithmeticEncoder& e, RgbModels& models, const std::uint8_t* last,
               const std::uint8_t* item) {
  std::array<std::int32_t, 3> lo{}, hi{}, last_lo{}, last_hi{};
  for (std::size_t c = 0; c < 3; ++c) {
    const auto v = load<std::uint16_t>(item + 2 * c);
    const auto l = load<std::uint16_t>(last + 2 * c);
    lo[c] = v & 0xff;
    hi[c] = v >> 8;
    last_lo[c] = l & 0xff;
    last_hi[c] = l >> 8;
  }
  std::uint32_t used = 0;
  for (std::uint32_t c = 0; c < 3; ++c) {
    used |= std::uint32_t{lo[c] != last_lo[c]} << (2 * c);
    used |= std::uint32_t{hi[c] != last_hi[c]} << (2 * c + 1);
  }
  const bool colour = lo[0] != lo[1] || lo[0] != lo[2] || hi[0] != hi[1] || hi[0] != hi[2];
  used |= std::uint32_t{colour} << 6;
  e.encodeSymbol(models.used, used);
  std::int32_t diff_lo = 0;
  std::int32_t diff_hi = 0;
  if (used & 1) {
    diff_lo = lo[0] - last_lo[0];
    e.encodeSymbol(models.diff[0], foldByte(diff_lo));
  }
  if (used & 2) {
    diff_hi = hi[0] - last_hi[0];
    e.encodeSymbol(models.diff[1], foldByte(diff_hi));
  }
  if (!colour) return;
  if (used & 4) e.encodeSymbol(models.diff[2], foldByte(lo[1] - clampByte(diff_lo + last_lo[1])));
  if (used & 16) {
    diff_lo = (diff_lo + lo[1] - last_lo[1]) / 2;
    e.encodeSymbol(models.diff[4], foldByte(lo[2] - clampByte(diff_lo + last_lo[2])));
  }
  if (used & 8) e.encodeSymbol(models.diff[3], foldByte(hi[1] - clampByte(diff_hi + last_hi[1])));
  if (used & 32) {
    diff_hi = (diff_hi + hi[1] - last_hi[1]) / 2;
    e.encodeSymbol(models.diff[5], foldByte(hi[2] - clampByte(diff_hi + last_hi[2])));
  }
}

}  // namespace octopoint::laz
