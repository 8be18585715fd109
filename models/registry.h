#pragma once
// The models compiled into this build (generated sources committed in models/), by name.

#include <span>
#include <string_view>

#include "renderer/embedded_model.h"

namespace octopoint::models {

// Every embedded model, the default first.
std::span<const EmbeddedModel* const> embeddedModels();
const EmbeddedModel* defaultModel();
// nullptr when there is no model of that name.
const EmbeddedModel* findModel(std::string_view name);

}  // namespace octopoint::models
