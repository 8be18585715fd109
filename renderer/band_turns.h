#pragma once
// What every band renderer (renderBands, renderPerspectiveBands) does between bands: the buffer a
// band is drawn into, alternating between two where the caller gives two, once the flush that
// last read it has finished.

#include <cstdint>
#include <span>

#include "octopoint/bands.h"

namespace octopoint {

inline std::span<std::uint8_t> bytesOf(std::span<std::uint32_t> words) {
  return {reinterpret_cast<std::uint8_t*>(words.data()), words.size() * 4};
}

// The buffer of band `band_number` (0 first), after sink.wait where it was flushed before.
inline std::span<std::uint32_t> bandBufferFor(const BandBuffers& buffers, int band_number,
                                              const BandSink& sink) {
  const int buffer_count = buffers.second.empty() ? 1 : 2;
  const std::span<std::uint32_t> buffer =
      (band_number & 1) != 0 && buffer_count == 2 ? buffers.second : buffers.first;
  if (band_number >= buffer_count && sink.wait != nullptr) sink.wait(sink.user, bytesOf(buffer));
  return buffer;
}

}  // namespace octopoint
