// The ncurses session: set up on construction, the terminal given back on destruction, whatever
// way the program leaves (return, exception; signals are turned into an orderly exit by the main
// loop). Also turns ncurses' key codes into the console's Keys.
#pragma once

#include <pc/core/key.hpp>

namespace qrterm {

class Terminal {
 public:
  Terminal();
  ~Terminal();
  Terminal(const Terminal&) = delete;
  Terminal& operator=(const Terminal&) = delete;

  // The next key typed, or kKeyNone when there is none (never waits, apart from the few ms that
  // tell a lone ESC from the start of an arrow key's sequence).
  Key next_key();

  // Gives the terminal back now (idempotent); the destructor does it too.
  void close();

 private:
  bool open_ = false;
};

// Colour pairs the cockpit draws with.
enum ColorPair : short { kInfo = 1, kWarning, kError, kQr, kAlarm, kTitle, kBar, kDim, kMagenta };

// Whether the terminal takes UTF-8 (the locale says so): the plot draws in braille then, else in
// plain characters.
bool terminal_speaks_utf8();

}  // namespace qrterm
