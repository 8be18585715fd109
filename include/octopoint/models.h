#pragma once
// octopoint/models.h: The models compiled into the library (the default model) and their registry.
// The manual of the whole library is octopoint/octopoint.h.

#include <span>
#include <string_view>

#include "octopoint/model.h"

// The models compiled into this build (generated sources committed in models/), by name.

namespace octopoint::models {

// Every embedded model, the default first.
std::span<const EmbeddedModel* const> embeddedModels();
const EmbeddedModel* defaultModel();
// nullptr when there is no model of that name.
[[nodiscard]] const EmbeddedModel* findModel(std::string_view name);

}  // namespace octopoint::models
