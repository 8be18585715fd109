// libFuzzer harness for the LAS reader and the streamed preparer behind it. Each input is written
// to an in-memory file and opened as LAS: a header that lies must end in one PrepareError line,
// nothing else. A file the reader accepts is then prepared whole (two depths, one thread, a budget
// that needs no disk): hostile scales, offsets and coordinates must give a valid model or a
// PrepareError, never a crash, a sanitizer report or a hang.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "codegen/las_reader.h"
#include "codegen/model_writer.h"
#include "codegen/prepare_error.h"
#include "codegen/streamed_prepare.h"
#include "octopoint/model.h"
#include "tests/support/memory_file.h"

namespace {

using namespace octopoint::prepare;

void expectOneLine(const PrepareError& error) {
  if (std::string(error.what()).find('\n') != std::string::npos) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static octopoint::fuzzing::MemoryFile file;
  const auto& path = file.write(data, size);
  try {
    const auto source = openLasSource(path);
    PrepareOptions options;
    options.name = "fuzz";
    options.depths = {3, 7};
    StreamOptions stream;
    stream.threads = 1;
    stream.memory_bytes = 64 << 20;
    const PreparedModel model = prepareFromSource(*source, "fuzz.las", options, stream);
    // Whatever was accepted must be a model the renderer's validator accepts too.
    const std::vector<std::uint8_t> image = serializeModel(model);
    octopoint::ModelIssue issue;
    if (!octopoint::ModelView::fromBytes(image, &issue)) std::abort();
  } catch (const PrepareError& error) {
    expectOneLine(error);
  }
  return 0;
}
