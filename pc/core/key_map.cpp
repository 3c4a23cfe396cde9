#include <pc/core/key_map.hpp>

#include <pc/core/action.hpp>

namespace qrterm {

Action action_for(Key key) {
  if (key >= 'A' && key <= 'Z') key = key - 'A' + 'a';
  for (const KeyBinding& binding : kKeyMap) {
    if (binding.key == key) return binding.action;
  }
  return Action::none;
}

const char* action_text(Action action) {
  for (const ActionSpec& spec : kActions) {
    if (spec.action == action) return spec.text;
  }
  return "";
}

}  // namespace qrterm
