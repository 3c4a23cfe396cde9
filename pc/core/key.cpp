#include <pc/core/key.hpp>

namespace qrterm {
namespace {

struct NamedKey {
  Key key;
  const char* name;
};

constexpr NamedKey kNamedKeys[] = {
    {kKeyEscape, "ESC"},
    {kKeyInterrupt, "^C"},
    {kKeyUp, "up"},
    {kKeyDown, "down"},
    {kKeyLeft, "left"},
    {kKeyRight, "right"},
    {' ', "space"},
    {kKeyTab, "Tab"},
    {kKeyEnter, "Enter"},
    {kKeyBackspace, "Backspace"},
    {19, "^S"},
    {15, "^O"},
    {20, "^T"},
    {18, "^R"},
    {kKeyPageUp, "PgUp"},
    {kKeyPageDown, "PgDn"},
    {kKeyHome, "Home"},
    {kKeyEnd, "End"},
    {kKeyInsert, "Insert"},
    {kKeyDelete, "Delete"},
    {kKeyBackTab, "Shift+Tab"},
};

}  // namespace

std::string key_name(Key key) {
  for (const NamedKey& named : kNamedKeys) {
    if (named.key == key) return named.name;
  }
  if (key >= kKeyF1 && key < kKeyF1 + kFunctionKeys) return "F" + std::to_string(key - kKeyF1 + 1);
  if (key > ' ' && key < 0x7F) return std::string(1, static_cast<char>(key));
  if (key >= 1 && key < ' ') return "^" + std::string(1, static_cast<char>('@' + key));  // a control key: ^A
  // "key code 300" in "key code 300 does nothing": a key without a name says what it is.
  return "code " + std::to_string(key);
}

}  // namespace qrterm
