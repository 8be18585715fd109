#pragma once
// The preparer's promise for bad input, checked: reading `path` throws one PrepareError whose
// message is one line, starts with the file's name and says `expected`.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "codegen/prepare_error.h"

namespace octopoint::testing {

template <typename Read>
void expectRefusedInOneLine(const std::filesystem::path& path, const std::string& expected,
                            Read read) {
  try {
    read(path);
    ADD_FAILURE() << path << " was read; expected '" << expected << "'";
  } catch (const prepare::PrepareError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_EQ(message.rfind(path.string(), 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace octopoint::testing
