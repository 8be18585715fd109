#pragma once
// Text from outside (an option's value, a key of a scene file, a file name) quoted in a message:
// printable, one line, and short enough to read.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace octopoint::cli {

inline constexpr std::size_t kMaxQuoted = 40;
inline constexpr std::size_t kMaxPathShown = 160;

// `text` with every byte outside printable ASCII as '?', cut to `max_chars` followed by "..."
// when longer. Never contains a line break.
std::string printable(std::string_view text, std::size_t max_chars = kMaxQuoted);

// printable() between single quotes: 'text'.
std::string inQuotes(std::string_view text, std::size_t max_chars = kMaxQuoted);

// A path for a message: printable, and cut in the middle ("/a/b/...c/scan.pcd") past
// kMaxPathShown characters so that its file name stays visible.
std::string displayPath(const std::filesystem::path& path);

// One line: every line break or other control character of `message` as a space.
std::string oneLine(std::string_view message);

// `value` as the shortest text that reads back as the same double (1000000.0625, not %g's
// 1e+06), in plain digits from 1e-6 to 1e16 and with an exponent beyond: a message about a
// number shows the number given, not a neighbour of it.
std::string realText(double value);

}  // namespace octopoint::cli
