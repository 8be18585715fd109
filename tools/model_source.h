#pragma once
// Where an app's model comes from: `--file M.oct` (read and validated) or `--model NAME` (one of
// the models embedded in this binary, validated too), the default model when neither is given.
// Shared by octopoint-render and octopoint-view so both refuse bad models the same way.

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/input_file.h"
#include "octopoint/model.h"
#include "octopoint/progressive.h"

namespace octopoint {

// A model that cannot be had: the message is the one line to show the user.
struct ModelLoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A model file: a regular file of at most 1 GiB (cli/input_file.h), stated in the tools' --help.
inline constexpr cli::InputKind kModelFileInput{"model file", cli::kGiB};

// The options that name a tool's model, as octopoint-render and octopoint-view read them: --model
// NAME, --file M.oct, --url URL (at most one of the three) and --point-budget N.
struct ModelSourceOptions {
  std::string model_name;
  std::string model_file;
  std::string url;
  std::uint64_t point_budget = 0;  // points drawn a frame of a chunked model; 0: no budget
};

// Reads the option `args` is at into `source`: false when it is none of the four.
bool parseModelSourceOption(cli::ArgumentReader& args, ModelSourceOptions& source);
// Throws cli::Error when more than one of --model, --file and --url was given.
void checkOneModelSource(const ModelSourceOptions& source);

struct LoadedModel {
  std::vector<std::uint8_t> file_bytes;  // the .oct image the view points into (empty if embedded)
  std::optional<ModelView> view;         // a version-1 model
  std::optional<ProgressiveModel> chunked;  // or a chunked one (version 3), read whole
  std::string label;  // the file path or the embedded model's name, for messages
};

// Throws ModelLoadError with one line ("PATH: what (where)") when the model is missing,
// unreadable or invalid. Returned by pointer: the view points into the object's own bytes. A file
// in the chunked format (version 3) is read whole into `chunked`; every part must be valid.
// Callers that cannot draw one pass accept_chunked = false and get a ModelLoadError for it.
std::unique_ptr<LoadedModel> loadModel(const std::string& model_name, const std::string& model_file,
                                       bool accept_chunked = false);

}  // namespace octopoint
