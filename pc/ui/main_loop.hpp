// The main loop: poll() on the serial line, the keyboard, the joystick and the simulator's
// output, with a 10 ms tick for the link's timers and a redraw at most every 100 ms. Nothing in
// it blocks: the link's 50 Hz heartbeat never waits for the screen.
#pragma once

#include <memory>

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
  SimProcess* sim = nullptr;         // null when flying a QR on --port
  JoystickDevice* joystick = nullptr;  // null with --no-joystick
  Terminal& terminal;
  Cockpit& cockpit;
};

// Runs until the console has finished its exit.
void run_main_loop(Session& session);

inline constexpr uint32_t kRedrawMs = 100;  // at most 10 screens a second
inline constexpr int kPollMs = 5;  // the longest a control message or a key waits

}  // namespace qrterm
