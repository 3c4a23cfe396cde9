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

std::vector<HelpEntry> help_entries() {
  std::vector<HelpEntry> entries;
  for (const KeyBinding& binding : kKeyMap) {
    HelpEntry* same = nullptr;
    for (HelpEntry& entry : entries) {
      if (entry.action == binding.action) same = &entry;
    }
    if (same != nullptr) {
      same->keys += " " + key_name(binding.key);
    } else {
      entries.push_back({key_name(binding.key), binding.action});
    }
  }
  return entries;
}

const char* action_text(Action action) {
  for (const ActionSpec& spec : kActions) {
    if (spec.action == action) return spec.text;
  }
  return "";
}

}  // namespace qrterm
