#include "app/model_source.h"

#include <filesystem>
#include <fstream>

#include "models/registry.h"

namespace octopoint {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t{1} << 30;

std::vector<std::uint8_t> readModelFile(const std::string& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) throw ModelLoadError(path + ": no such model file");
  const std::uintmax_t size = fs::file_size(path, error);
  if (error || size > kMaxModelFileBytes) throw ModelLoadError(path + ": unreadable or larger than 1 GiB");
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!in) throw ModelLoadError(path + ": read failed");
  return bytes;
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) on chains of string + here.
std::string issueText(const ModelIssue& issue) {
  std::string text = describe(issue.error);
  if (issue.depth != 0) {
    text += " (depth ";
    text += std::to_string(issue.depth);
    text += " stream";
  } else {
    text += " (file";
  }
  text += ", byte ";
  text += std::to_string(issue.offset);
  text += ')';
  return text;
}

}  // namespace

std::unique_ptr<LoadedModel> loadModel(const std::string& model_name, const std::string& model_file) {
  auto loaded = std::make_unique<LoadedModel>();
  ModelIssue issue;
  if (!model_file.empty()) {
    loaded->file_bytes = readModelFile(model_file);
    loaded->view = ModelView::fromBytes(loaded->file_bytes, &issue);
    loaded->label = model_file;
  } else {
    const EmbeddedModel* embedded = model_name.empty() ? models::defaultModel() : models::findModel(model_name);
    if (embedded == nullptr) throw ModelLoadError("--model: no embedded model '" + model_name + "' (see --list)");
    loaded->view = ModelView::fromEmbedded(*embedded, &issue);
    loaded->label = embedded->name;
  }
  if (!loaded->view) throw ModelLoadError(loaded->label + ": " + issueText(issue));
  return loaded;
}

}  // namespace octopoint
