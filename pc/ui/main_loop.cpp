#include <pc/ui/main_loop.hpp>

#include <poll.h>
#include <unistd.h>

#include <pc/platform/clock.hpp>
#include <pc/platform/signals.hpp>

namespace qrterm {
namespace {

// How often a lost joystick is looked for, and the simulator asked whether it still runs.
constexpr uint32_t kJoystickRetryMs = 1000;
constexpr uint32_t kChildCheckMs = 100;

void read_joystick(Session& s, uint32_t now) {
  JoystickDevice& joystick = *s.joystick;
  if (!joystick.read()) {
    s.console.joystick_lost(now);  // once: the console knows it is lost already after that
    return;
  }
  JoystickReader& reader = joystick.reader();
  // A device opened again counts as back once it has said where the stick is: one that opens but
  // delivers nothing (a half-gone USB device) is not a joystick.
  if (s.console.joystick_state() == JoystickState::lost) {
    if (!reader.position_known()) return;
    s.console.joystick_back(now);
  }
  if (reader.take_abort()) s.console.joystick_fire(now);
  s.console.joystick_moved(reader.sticks(), reader.position_known(), now);
}

void read_sim_output(Session& s, LineReader& reader, bool& open, Severity severity) {
  for (const std::string& line : reader.read(open)) s.console.note(severity, "sim: " + line);
}

}  // namespace

void run_main_loop(Session& s) {
  Console& console = s.console;
  bool serial_open = true;
  bool sim_out_open = s.sim != nullptr;
  bool sim_err_open = s.sim != nullptr;
  bool sim_ended = false;
  int signals_handled = 0;
  uint32_t last_draw = monotonic_ms() - kRedrawMs;
  uint32_t last_child_check = monotonic_ms();
  uint32_t last_joystick_retry = monotonic_ms();
  std::vector<uint8_t> received;
  std::string why;

  while (!console.finished()) {
    enum { kSerial, kKeyboard, kJoystick, kSimOut, kSimErr, kCount };
    pollfd fds[kCount] = {};
    fds[kSerial] = {serial_open ? s.serial.fd() : -1, POLLIN, 0};
    fds[kKeyboard] = {STDIN_FILENO, POLLIN, 0};
    fds[kJoystick] = {s.joystick != nullptr ? s.joystick->fd() : -1, POLLIN, 0};
    fds[kSimOut] = {sim_out_open ? s.sim->out().fd() : -1, POLLIN, 0};
    fds[kSimErr] = {sim_err_open ? s.sim->err().fd() : -1, POLLIN, 0};
    ::poll(fds, kCount, kPollMs);
    const uint32_t now = monotonic_ms();

    if (serial_open && fds[kSerial].revents != 0) {
      received.clear();
      const SerialPort::Io io = s.serial.read_available(received, why);
      console.receive(received.data(), received.size(), now);
      if (io == SerialPort::Io::closed) {
        serial_open = false;
        console.line_closed(why, now);
      }
    }
    // Each key with its own time: telling ESC from an arrow key can take a few ms.
    for (Key key = s.terminal.next_key(); key != kKeyNone; key = s.terminal.next_key()) console.key(key, monotonic_ms());
    if (s.joystick != nullptr) {
      if (fds[kJoystick].fd >= 0 && fds[kJoystick].revents != 0) {
        read_joystick(s, now);
      } else if (s.joystick->fd() < 0 && now - last_joystick_retry >= kJoystickRetryMs) {
        last_joystick_retry = now;
        s.joystick->reopen();
      }
    }
    if (sim_out_open && fds[kSimOut].revents != 0) read_sim_output(s, s.sim->out(), sim_out_open, Severity::info);
    if (sim_err_open && fds[kSimErr].revents != 0) read_sim_output(s, s.sim->err(), sim_err_open, Severity::warning);
    if (s.sim != nullptr && !sim_ended && now - last_child_check >= kChildCheckMs) {
      last_child_check = now;
      if (const std::optional<std::string> how = s.sim->ended()) {
        sim_ended = true;
        console.line_closed(*how, now);
      }
    }
    for (; signals_handled < exit_signals(); ++signals_handled) {
      console.note(Severity::warning, "signal: exiting");
      console.request_exit(now);
    }

    console.tick(now);
    if (serial_open && s.serial.write_some(console.output(), why) == SerialPort::Io::closed) {
      serial_open = false;
      console.line_closed(why, now);
    }
    if (!serial_open) console.output().clear();
    if (now - last_draw >= kRedrawMs) {
      last_draw = now;
      s.cockpit.draw(console);
    }
  }
  s.cockpit.draw(console);
}

}  // namespace qrterm
