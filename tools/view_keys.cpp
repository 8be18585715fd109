#include "tools/view_keys.h"

#include <algorithm>
#include <utility>

namespace octopoint {

void KeyBindings::hold(std::vector<SDL_Keycode> keys, std::string label, std::string help,
                       NavigationKey navigation) {
  KeyBinding binding;
  binding.keys = std::move(keys);
  binding.label = std::move(label);
  binding.help = std::move(help);
  binding.navigation = navigation;
  bindings_.push_back(std::move(binding));
}

void KeyBindings::press(std::vector<SDL_Keycode> keys, std::string label, std::string help,
                        std::function<void(std::int64_t now_us)> action, bool repeats) {
  KeyBinding binding;
  binding.keys = std::move(keys);
  binding.label = std::move(label);
  binding.help = std::move(help);
  binding.action = std::move(action);
  binding.repeats = repeats;
  bindings_.push_back(std::move(binding));
}

void KeyBindings::walkHold(std::vector<SDL_Keycode> keys, std::string label, std::string help,
                           NavigationKey navigation,
                           std::function<void(std::int64_t now_us)> action) {
  KeyBinding binding;
  binding.keys = std::move(keys);
  binding.label = std::move(label);
  binding.help = std::move(help);
  binding.walk_navigation = navigation;
  binding.action = std::move(action);
  bindings_.push_back(std::move(binding));
}

void KeyBindings::describe(std::string label, std::string help) {
  KeyBinding binding;
  binding.label = std::move(label);
  binding.help = std::move(help);
  bindings_.push_back(std::move(binding));
}

const KeyBinding* KeyBindings::find(SDL_Keycode key) const {
  for (const KeyBinding& binding : bindings_) {
    if (std::find(binding.keys.begin(), binding.keys.end(), key) != binding.keys.end()) {
      return &binding;
    }
  }
  return nullptr;
}

std::string KeyBindings::helpText() const {
  std::size_t width = 0;
  for (const KeyBinding& binding : bindings_) width = std::max(width, binding.label.size());
  std::string text;
  for (const KeyBinding& binding : bindings_) {
    if (binding.help.empty()) continue;
    text += "  " + binding.label + std::string(width - binding.label.size() + 2, ' ') +
            binding.help + "\n";
  }
  return text;
}

}  // namespace octopoint
