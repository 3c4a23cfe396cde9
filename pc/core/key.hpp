// A key as the console sees it: a character code, or one of the named keys below. The screen
// layer translates its terminal library's codes into these, so the key map knows nothing of
// ncurses and can be tested without a terminal.
#pragma once

#include <stdint.h>

#include <string>

namespace qrterm {

using Key = int32_t;

inline constexpr Key kKeyNone = -1;
inline constexpr Key kKeyEscape = 27;
inline constexpr Key kKeyInterrupt = 3;  // ^C: the terminal is raw, so it is a key, not a signal
inline constexpr Key kKeyTab = 9;
inline constexpr Key kKeyEnter = 13;  // the raw terminal's carriage return; the screen layer maps the others here
// Outside the range of characters, so they never collide with a typed letter.
inline constexpr Key kKeyUp = 0x110000;
inline constexpr Key kKeyDown = 0x110001;
inline constexpr Key kKeyLeft = 0x110002;
inline constexpr Key kKeyRight = 0x110003;
inline constexpr Key kKeyBackspace = 0x110004;
inline constexpr Key kKeyPageUp = 0x110005;
inline constexpr Key kKeyPageDown = 0x110006;
inline constexpr Key kKeyHome = 0x110007;
// Keys no screen binds, named so that "key F1 does nothing" says which key it was, not a code.
inline constexpr Key kKeyEnd = 0x110008;
inline constexpr Key kKeyInsert = 0x110009;
inline constexpr Key kKeyDelete = 0x11000A;
inline constexpr Key kKeyBackTab = 0x11000B;  // Shift+Tab
inline constexpr Key kKeyF1 = 0x110010;       // F1 .. F12: kKeyF1 + 0 .. 11
inline constexpr int kFunctionKeys = 12;

// "ESC", "up", "a", "?", "F1": what the help overlay and the documentation call the key.
std::string key_name(Key key);

}  // namespace qrterm
