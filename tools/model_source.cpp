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

// "file size does not fit the tables and chunk offsets (level 0, byte 1073741824)".
std::string chunkedIssueText(const ChunkedIssue& issue) {
  return std::string(describe(issue.error)) + " (level " + std::to_string(issue.level) + ", byte " +
         std::to_string(issue.offset) + ")";
}

// What a model file's first bytes must hold for its declared sizes to be checked: the largest
// version 1, 2, 4 or 6 header with its level table (2,454 bytes), or a chunked file's fixed header.
constexpr std::size_t kModelHeadProbe = 4096;

// Refuses a file whose head (read into `bytes`, whole when the head says how long it is) declares
// another size than the file's, before its body is read: a lie costs a few kilobytes to refuse,
// not the file's size in memory.
void checkDeclaredSize(cli::InputFile& file, std::vector<std::uint8_t>& bytes,
                       const std::string& label, bool accept_chunked) {
  if (!looksChunked(bytes)) {
    ModelIssue issue;
    if (!ModelView::checkDeclaredSizes(bytes, file.size(), &issue))
      throw ModelLoadError(label + ": " + issueText(issue));
    return;
  }
  if (!accept_chunked)
    throw ModelLoadError(label + ": a chunked model (format version 3 or 5) cannot be shown here");
  ChunkedIssue issue;
  const std::optional<std::uint64_t> head_bytes = chunkedHeadBytes(bytes, &issue);
  if (head_bytes && *head_bytes > file.size()) issue = {ChunkedError::kBadFileSize, file.size(), 0};
  if (issue.error == ChunkedError::kNone && bytes.size() < *head_bytes)
    file.readUpTo(bytes, static_cast<std::size_t>(*head_bytes - bytes.size()));
  const std::optional<ChunkedHead> head =
      issue.error == ChunkedError::kNone ? parseChunkedHead(bytes, &issue) : std::nullopt;
  if (head && head->file_bytes != file.size()) issue = {ChunkedError::kBadFileSize, file.size(), 0};
  if (issue.error != ChunkedError::kNone)
    throw ModelLoadError(label + ": " + chunkedIssueText(issue));
}

// The bytes of a model file, read only when its head accounts for exactly the file's size.
std::vector<std::uint8_t> readModelFile(const std::string& path, const std::string& label,
                                        bool accept_chunked) {
  cli::InputFile file(path, kModelFileInput);
  std::vector<std::uint8_t> bytes;
  file.readUpTo(bytes, kModelHeadProbe);
  if (bytes.size() < file.size()) checkDeclaredSize(file, bytes, label, accept_chunked);
  file.readRest(bytes);
  return bytes;
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
  // An empty name would otherwise count as no source at all, and the default model be drawn.
  if (args.is("--model") || args.is("--file") || args.is("--url")) {
    const std::string& given = args.is("--model")  ? source.model_name
                               : args.is("--file") ? source.model_file
                                                   : source.url;
    if (given.empty()) throw cli::Error(std::string(args.name()) + ": empty (give a value)");
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
    loaded->label = cli::displayPath(model_file);
    loaded->file_bytes = readModelFile(model_file, loaded->label, accept_chunked);
    if (looksChunked(loaded->file_bytes)) {
      if (!accept_chunked)
        throw ModelLoadError(loaded->label +
                             ": a chunked model (format version 3 or 5) cannot be shown here");
      ChunkedIssue chunked_issue;
      loaded->chunked = progressiveModelFromPrefix(loaded->file_bytes, &chunked_issue);
      if (chunked_issue.error == ChunkedError::kNone && loaded->chunked &&
          loaded->chunked->head().file_bytes != loaded->file_bytes.size()) {
        chunked_issue = {ChunkedError::kBadFileSize, loaded->file_bytes.size(), 0};
      }
      if (chunked_issue.error != ChunkedError::kNone)
        throw ModelLoadError(loaded->label + ": " + chunkedIssueText(chunked_issue));
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
