#include "octopoint/models.h"

#include <array>

#include "models/tabletop/tabletop.h"

namespace octopoint::models {
namespace {

// The default model comes first.
constexpr std::array<const EmbeddedModel*, 1> kModels = {&tabletop};

}  // namespace

std::span<const EmbeddedModel* const> embeddedModels() { return kModels; }

const EmbeddedModel* defaultModel() { return kModels.front(); }

const EmbeddedModel* findModel(std::string_view name) {
  for (const EmbeddedModel* model : kModels) {
    if (name == model->name) return model;
  }
  return nullptr;
}

}  // namespace octopoint::models
