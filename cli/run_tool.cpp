#include "cli/run_tool.h"

#include <cstdio>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

#include "cli/text.h"

namespace octopoint::cli {

void printError(const char* tool_name, const char* message) {
  std::fprintf(stderr, "%s: %s\n", tool_name, oneLine(message).c_str());
  std::fflush(stderr);
}

int runTool(const char* tool_name, int argc, char** argv, ToolMain run) {
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    printError(tool_name, "out of memory");
  } catch (const std::runtime_error& error) {
    printError(tool_name, error.what());
  } catch (const std::exception& error) {
    printError(tool_name, (std::string("internal error: ") + error.what()).c_str());
  }
  return 1;
}

}  // namespace octopoint::cli
