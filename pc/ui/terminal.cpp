#include <pc/ui/terminal.hpp>

#include <langinfo.h>
#include <ncurses.h>

#include <clocale>
#include <cstring>

namespace qrterm {
namespace {

struct KeyCode {
  int curses;
  Key key;
};

// 127 is what most terminals send for Backspace, 8 what the others do.
constexpr KeyCode kKeyCodes[] = {
    {KEY_UP, kKeyUp},          {KEY_DOWN, kKeyDown},           {KEY_LEFT, kKeyLeft},
    {KEY_RIGHT, kKeyRight},    {KEY_BACKSPACE, kKeyBackspace}, {KEY_PPAGE, kKeyPageUp},
    {KEY_NPAGE, kKeyPageDown}, {KEY_HOME, kKeyHome},           {127, kKeyBackspace},
    {8, kKeyBackspace},        {KEY_ENTER, kKeyEnter},         {'\n', kKeyEnter},
    {KEY_END, kKeyEnd},        {KEY_IC, kKeyInsert},           {KEY_DC, kKeyDelete},
    {KEY_BTAB, kKeyBackTab},
};

// A lone ESC is told from an arrow key's escape sequence by waiting this long for the rest. Short:
// ESC is the abort key.
constexpr int kEscapeDelayMs = 25;

}  // namespace
}  // namespace qrterm

// Present only when the program is linked with the wide-character curses (a build directory
// configured before pc/CMakeLists.txt asked for it links the narrow one, which would print UTF-8
// as escapes).
#pragma weak wadd_wchnstr

namespace qrterm {

bool terminal_speaks_utf8() {
  const char* codeset = ::nl_langinfo(CODESET);
  return codeset != nullptr && std::strcmp(codeset, "UTF-8") == 0 && &wadd_wchnstr != nullptr;
}

Terminal::Terminal() {
  // The user's locale, so the wide-character curses writes UTF-8 (the plot's braille) when the
  // terminal takes it; under C or POSIX everything stays plain ASCII.
  std::setlocale(LC_ALL, "");
  ::initscr();
  open_ = true;
  // Raw, not cbreak: no ^S (XOFF) to freeze the screen, no ^Z to suspend the console and with it
  // the heartbeat. ^C arrives as a key, bound to exit like x.
  ::raw();
  ::noecho();
  ::nonl();
  ::keypad(stdscr, TRUE);
  ::nodelay(stdscr, TRUE);
  ::set_escdelay(kEscapeDelayMs);
  ::curs_set(0);
  if (::has_colors()) {
    ::start_color();
    ::use_default_colors();
    ::init_pair(kInfo, COLOR_GREEN, -1);
    ::init_pair(kWarning, COLOR_YELLOW, -1);
    ::init_pair(kError, COLOR_RED, -1);
    ::init_pair(kQr, COLOR_CYAN, -1);
    ::init_pair(kAlarm, COLOR_WHITE, COLOR_RED);
    ::init_pair(kTitle, COLOR_BLACK, COLOR_CYAN);
    ::init_pair(kBar, COLOR_GREEN, -1);
    ::init_pair(kDim, COLOR_BLUE, -1);
    ::init_pair(kMagenta, COLOR_MAGENTA, -1);
  }
}

Terminal::~Terminal() { close(); }

void Terminal::close() {
  if (!open_) return;
  ::endwin();
  open_ = false;
}

Key Terminal::next_key() {
  for (;;) {
    const int code = ::getch();
    if (code == ERR) return kKeyNone;
    if (code == KEY_RESIZE) continue;  // the cockpit reads the size at every draw
    for (const KeyCode& entry : kKeyCodes) {
      if (entry.curses == code) return entry.key;
    }
    if (code >= KEY_F(1) && code < KEY_F(1) + kFunctionKeys) return kKeyF1 + (code - KEY_F(1));
    return code;
  }
}

}  // namespace qrterm
