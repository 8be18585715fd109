#pragma once
// The one error type of the command-line helpers: its message is the single line a tool prints on
// stderr after its own name ("octopoint-render: --size: '0x10' ..."), so it names the option or
// the file and says what is wrong, without a newline.

#include <stdexcept>
#include <string>

namespace octopoint::cli {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace octopoint::cli
