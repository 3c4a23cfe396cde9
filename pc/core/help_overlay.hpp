// The help overlay's layout (docs/console.md "Keys"): the key map's entries in columns, in a box
// below the title, MODE/LINK, battery, QR and engine rows, so a pilot reading it in flight still
// sees the mode, the link and the engines. Computed here, without a terminal, so a test can read
// the rows the screen would show.
#pragma once

#include <stddef.h>

#include <string>
#include <vector>

namespace qrterm {

// The rows above the overlay that it must leave visible (title, MODE/LINK, battery, QR, engines).
inline constexpr int kHelpTopRow = 8;
// Between two columns: one space would run an entry's text into the next column's key.
inline constexpr int kHelpColumnGap = 2;

struct HelpOverlay {
  int top = 0;
  int left = 0;
  int width = 0;
  std::vector<std::string> rows;  // each `width` characters: the title, then the entries' rows
};

// The overlay for a terminal of `rows` x `columns`: two columns where the rows allow, else three.
// The title names the keys no entry holds: Tab (the next screen) and how to close it.
HelpOverlay help_overlay(int rows, int columns);

}  // namespace qrterm
