// The main loop, as two threads sharing the Console under one lock:
//   the link thread: poll() on the serial line, the Console's timers every few ms (control at
//   50 Hz, resends, link state), writes to the line; it never waits for anything else;
//   the UI thread: keys, the joystick, the simulator's output, signals, and at most 10 screens a
//   second, composed under the lock and written to the terminal outside it.
// A terminal that stops taking output (frozen, XOFF) stalls the screen, never the heartbeat.
#pragma once

#include <pc/core/console.hpp>
#include <pc/platform/joystick_device.hpp>
#include <pc/platform/serial_port.hpp>
#include <pc/platform/sim_process.hpp>
#include <pc/ui/cockpit.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {

struct Session {
  Console& console;
  SerialPort& serial;
  SimProcess* sim = nullptr;           // null when flying a QR on --port
  JoystickDevice* joystick = nullptr;  // null with --no-joystick
  Terminal& terminal;
  Cockpit& cockpit;
};

// Runs until the console has finished its exit.
void run_main_loop(Session& session);

inline constexpr uint32_t kRedrawMs = 100;     // at most 10 screens a second
inline constexpr uint32_t kPlotRedrawMs = 40;  // the plot screen: 25 a second
// The link thread's pass: at most one every this many ms, and one at least that often. The
// simulator hands over a few bytes every ms; a pass for each (some 900 a second, each a wake-up,
// a read and the lock) cost more CPU than the plot's drawing. A control message waits at most
// this past its time.
inline constexpr int kLinkPassMs = 4;
inline constexpr int kUiPollMs = 10;

}  // namespace qrterm
