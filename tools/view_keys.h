#pragma once
// The viewer's keys as one table (tools/view_main.cpp fills it): what each key does, and the help
// text printed by --help, which is generated from the same table so the two cannot disagree.
//
// Two kinds of binding. A held key (the arrows) is a NavigationKey of the dual-resolution renderer:
// its press and its release go to the renderer as they happen (SDL2 reports both; the keyboard's
// auto-repeat is not a press). Any other key runs an action when it goes down, and again on each
// auto-repeat if the binding says so (zooming repeats, saving does not).
//
// To add a key (a style to cycle, a light to move): one press() call with a label, a help line and
// the action, next to the others in tools/view_main.cpp.

#include <SDL2/SDL_keycode.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "octopoint/interactive.h"

namespace octopoint {

struct KeyBinding {
  std::vector<SDL_Keycode> keys;
  std::string label;  // how --help names the keys, e.g. "+ -"
  std::string help;
  std::optional<NavigationKey> navigation;       // a held key: press and release go to the renderer
  std::optional<NavigationKey> walk_navigation;  // the same in walk mode, instead of the action
  std::function<void(std::int64_t now_us)> action;  // otherwise: run when the key goes down
  bool repeats = false;                             // the action also runs on auto-repeat
};

class KeyBindings {
 public:
  // A navigation key, held to turn the view.
  void hold(std::vector<SDL_Keycode> keys, std::string label, std::string help,
            NavigationKey navigation);
  // A key that acts when pressed. One label and help line may describe several bindings: give
  // the label and help to the first and leave both empty on the others.
  void press(std::vector<SDL_Keycode> keys, std::string label, std::string help,
             std::function<void(std::int64_t now_us)> action, bool repeats = false);
  // A key held in walk mode to move the eye, that acts when pressed in orbit mode (`action` may
  // be empty: then it does nothing there).
  void walkHold(std::vector<SDL_Keycode> keys, std::string label, std::string help,
                NavigationKey navigation, std::function<void(std::int64_t now_us)> action = {});

  // A help line only, for an input that is not a key (the mouse wheel).
  void describe(std::string label, std::string help);

  // The binding of `key`, or nullptr.
  const KeyBinding* find(SDL_Keycode key) const;
  const std::vector<KeyBinding>& all() const { return bindings_; }

  // "  LABEL  help" lines, the labels padded to one column.
  std::string helpText() const;

 private:
  std::vector<KeyBinding> bindings_;
};

}  // namespace octopoint
