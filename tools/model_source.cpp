#include "tools/model_source.h"

#include "cli/error.h"
#include "cli/input_file.h"
#include "cli/numbers.h"
#include "cli/text.h"
#include "octopoint/models.h"

namespace octopoint {
namespace {

// "bad magic (file byte 0)", "zero mask byte (depth 8, file byte 1234)": the byte a hex editor
// shows. Built by appending: GCC 12 warns falsely (-Wrestrict) on chains of string + here.
std::string issueText(const ModelIssue& issue) {
  std::string text = describe(issue.error);
  text += " (";
  if (issue.depth != 0) {
    text += "depth ";
    text += std::to_string(issue.depth);
    text += ", ";
  }
  text += issue.offset_in_file ? "file byte " : "stream byte ";
  text += std::to_string(issue.offset);
  text += ')';
  return text;
}

}  // namespace

bool parseModelSourceOption(cli::ArgumentReader& args, ModelSourceOptions& source) {
  if (args.is("--model")) {
    source.model_name = args.value();
  } else if (args.is("--file")) {
    source.model_file = args.value();
  } else if (args.is("--url")) {
    source.url = args.value();
  } else if (args.is("--point-budget")) {
    source.point_budget = static_cast<std::uint64_t>(
        cli::parseInteger(args.name(), args.value(), 1, std::int64_t{1} << 40));
  } else {
    return false;
  }
  return true;
}

void checkOneModelSource(const ModelSourceOptions& source) {
  if (!source.model_name.empty() + !source.model_file.empty() + !source.url.empty() > 1)
    throw cli::Error("give one of --model, --file and --url");
}

std::unique_ptr<LoadedModel> loadModel(const std::string& model_name, const std::string& model_file,
                                       bool accept_chunked) {
  auto loaded = std::make_unique<LoadedModel>();
  ModelIssue issue;
  if (!model_file.empty()) {
    loaded->file_bytes = cli::readInputBytes(model_file, kModelFileInput);
    loaded->label = cli::displayPath(model_file);
    if (looksChunked(loaded->file_bytes)) {
      if (!accept_chunked)
        throw ModelLoadError(loaded->label +
                             ": a chunked model (format version 3) cannot be shown here");
      ChunkedIssue chunked_issue;
      loaded->chunked = progressiveModelFromPrefix(loaded->file_bytes, &chunked_issue);
      if (chunked_issue.error == ChunkedError::kNone && loaded->chunked &&
          loaded->chunked->head().file_bytes != loaded->file_bytes.size()) {
        chunked_issue = {ChunkedError::kBadFileSize, loaded->file_bytes.size(), 0};
      }
      if (chunked_issue.error != ChunkedError::kNone) {
        throw ModelLoadError(loaded->label + ": " + describe(chunked_issue.error) + " (level " +
                             std::to_string(chunked_issue.level) + ", byte " +
                             std::to_string(chunked_issue.offset) + ")");
      }
      return loaded;
    }
    loaded->view = ModelView::fromBytes(loaded->file_bytes, &issue);
  } else {
    const EmbeddedModel* embedded =
        model_name.empty() ? models::defaultModel() : models::findModel(model_name);
    if (embedded == nullptr)
      throw ModelLoadError("--model: no embedded model " + cli::inQuotes(model_name) +
                           " (see --list)");
    loaded->view = ModelView::fromEmbedded(*embedded, &issue);
    loaded->label = embedded->name;
  }
  if (!loaded->view) throw ModelLoadError(loaded->label + ": " + issueText(issue));
  return loaded;
}

}  // namespace octopoint
