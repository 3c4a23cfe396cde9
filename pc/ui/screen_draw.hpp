// What every screen of qrterm draws with: formatted text, and text put at a place, cut at the
// right edge.
#pragma once

#include <ncurses.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <string>

namespace qrterm {

std::string text(const char* format, ...) __attribute__((format(printf, 1, 2)));
inline std::string text(const char* format, ...) {
  char buffer[512];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(buffer, sizeof buffer, format, arguments);
  va_end(arguments);
  return buffer;
}

// Writes `s` at (row, column), cut at the right edge.
inline void put(int row, int column, const std::string& s, short pair = 0, attr_t attributes = A_NORMAL) {
  const int room = COLS - column;
  if (row < 0 || row >= LINES || room <= 0) return;
  attron(COLOR_PAIR(pair) | attributes);
  mvaddnstr(row, column, s.c_str(), std::min(room, static_cast<int>(s.size())));
  attroff(COLOR_PAIR(pair) | attributes);
}

}  // namespace qrterm
