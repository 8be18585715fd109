#include "app/model_source.h"

#include "cli/input_file.h"
#include "cli/text.h"
#include "models/registry.h"

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

std::unique_ptr<LoadedModel> loadModel(const std::string& model_name, const std::string& model_file) {
  auto loaded = std::make_unique<LoadedModel>();
  ModelIssue issue;
  if (!model_file.empty()) {
    loaded->file_bytes = cli::readInputBytes(model_file, kModelFileInput);
    loaded->view = ModelView::fromBytes(loaded->file_bytes, &issue);
    loaded->label = cli::displayPath(model_file);
  } else {
    const EmbeddedModel* embedded = model_name.empty() ? models::defaultModel() : models::findModel(model_name);
    if (embedded == nullptr) throw ModelLoadError("--model: no embedded model " + cli::inQuotes(model_name) + " (see --list)");
    loaded->view = ModelView::fromEmbedded(*embedded, &issue);
    loaded->label = embedded->name;
  }
  if (!loaded->view) throw ModelLoadError(loaded->label + ": " + issueText(issue));
  return loaded;
}

}  // namespace octopoint
