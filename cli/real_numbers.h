#pragma once
// Strict parsing of the decimal numbers users pass as options (angles, zoom), host tools only:
// the whole text is one finite number in a stated range, or a cli::Error names the option.
// Floating point lives here, on the host side; the renderer sees only the integer results.

#include <string_view>

#include "octopoint/fixed.h"

namespace octopoint::cli {

// The largest |angle| in degrees an option takes: far beyond any use, and exact in millidegrees.
inline constexpr double kMaxDegrees = 1e6;
// The zoom's Q16.16 range: 1/65536 (one raw step) to 32767.
inline constexpr double kMinZoom = 1.0 / 65536;
inline constexpr double kMaxZoom = 32767;

// "--zoom: 'abc' is not a number (1/65536..32767)" / "--zoom: 1e400 is outside 1/65536..32767".
// `shown_range` replaces the "%g..%g" of low and high in messages when given.
double parseReal(std::string_view option, std::string_view text, double low, double high,
                 std::string_view shown_range = {});

// Degrees in [-kMaxDegrees, kMaxDegrees], rounded to the nearest millidegree, then to the
// integer angle (1/65536 turn) as Angle::fromMilliDegrees rounds.
Angle parseDegrees(std::string_view option, std::string_view text);

// A zoom ratio in [kMinZoom, kMaxZoom], rounded to the nearest Q16.16 step.
Q16 parseZoom(std::string_view option, std::string_view text);

}  // namespace octopoint::cli
