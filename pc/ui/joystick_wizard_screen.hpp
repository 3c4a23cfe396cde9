// The joystick wizard's screen (qrterm --joystick-wizard): the steps with what each found, the
// current step's instruction, what the joystick does now, and at the end what will be written or
// why it will not. It runs instead of the cockpit, before any link is opened: the map it writes is
// read at the next start. The logic is pc/core/joystick_wizard.*; this only shows it and takes keys.
#pragma once

#include <string>

#include <pc/ui/terminal.hpp>

namespace qrterm {

struct WizardOutcome {
  int status = 0;       // 0: the map was written; 1: nothing was written
  std::string message;  // for the ordinary terminal, after the screen has closed
};

struct WizardFiles {
  int joystick_fd = -1;  // non-blocking, delivering js_event records
  std::string joystick;  // its path, for the title and the messages
  std::string map;       // the map file to write
};

// Runs until the map is written, the pilot leaves (ESC, ^C, a signal) or the joystick goes away.
WizardOutcome run_joystick_wizard(const WizardFiles& files, Terminal& terminal);

}  // namespace qrterm
