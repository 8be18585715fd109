#pragma once
// The one error type of the preparer. Its message is the single line the CLI prints on stderr:
// "<file>: <what went wrong> (<where>)", so it must name the file and the place, and end without
// a newline.

#include <stdexcept>
#include <string>

namespace octopoint::prepare {

class PrepareError : public std::runtime_error {
 public:
  explicit PrepareError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace octopoint::prepare
