#include "cli/text.h"

#include <charconv>
#include <system_error>

namespace octopoint::cli {
namespace {

bool isPrintable(char c) { return c >= 0x20 && c < 0x7f; }

}  // namespace

std::string printable(std::string_view text, std::size_t max_chars) {
  std::string out;
  for (char c : text.substr(0, max_chars)) out += isPrintable(c) ? c : '?';
  if (text.size() > max_chars) out += "...";
  return out;
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "'" + string.
std::string inQuotes(std::string_view text, std::size_t max_chars) {
  std::string out = "'";
  out += printable(text, max_chars);
  out += '\'';
  return out;
}

std::string displayPath(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.size() <= kMaxPathShown) return printable(text, kMaxPathShown);
  constexpr std::size_t kHead = kMaxPathShown / 3;
  constexpr std::size_t kTail = kMaxPathShown - kHead;
  return printable(std::string_view(text).substr(0, kHead), kHead) + "..." +
         printable(std::string_view(text).substr(text.size() - kTail), kTail);
}

std::string oneLine(std::string_view message) {
  std::string out(message);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  }
  return out;
}

std::string realText(double value) {
  char text[64];
  // Plain digits where they stay short (1000000, not 1e+06); exponents for the far ends.
  const double size = value < 0 ? -value : value;
  const bool plain = size == 0 || (size >= 1e-6 && size < 1e16);
  const auto [end, error] =
      plain ? std::to_chars(text, text + sizeof text, value, std::chars_format::fixed)
            : std::to_chars(text, text + sizeof text, value);
  if (error != std::errc()) return "?";  // 64 characters hold every double
  return std::string(text, end);
}

}  // namespace octopoint::cli
