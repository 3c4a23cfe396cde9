#include <pc/ui/main_loop.hpp>

#include <poll.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include <pc/platform/clock.hpp>
#include <pc/platform/signals.hpp>

namespace qrterm {
namespace {

// How often a lost joystick is looked for, and the simulator asked whether it still runs.
constexpr uint32_t kJoystickRetryMs = 1000;
constexpr uint32_t kChildCheckMs = 100;

void run_link(Session& s, std::mutex& lock, const std::atomic<bool>& stop) {
  bool serial_open = true;
  std::vector<uint8_t> received;
  std::string why;
  auto last_pass = std::chrono::steady_clock::now();
  while (!stop) {
    const auto next_pass = last_pass + std::chrono::milliseconds(kLinkPassMs);
    pollfd fd{serial_open ? s.serial.fd() : -1, POLLIN, 0};
    ::poll(&fd, 1, kLinkPassMs);
    // Bytes that woke the poll early gather until the pass is due.
    std::this_thread::sleep_until(next_pass);
    last_pass = std::chrono::steady_clock::now();
    const uint32_t now = monotonic_ms();
    received.clear();
    const SerialPort::Io io = serial_open && fd.revents != 0 ? s.serial.read_available(received, why)
                                                             : SerialPort::Io::ok;

    const std::lock_guard<std::mutex> hold(lock);
    s.console.receive(received.data(), received.size(), now);
    if (io == SerialPort::Io::closed) {
      serial_open = false;
      s.console.line_closed(why, now);
    }
    s.console.tick(now);
    // Non-blocking: what the line does not take now waits for the next pass.
    if (serial_open && s.serial.write_some(s.console.output(), why) == SerialPort::Io::closed) {
      serial_open = false;
      s.console.line_closed(why, now);
    }
    if (!serial_open) s.console.output().clear();
  }
}

class Ui {
 public:
  explicit Ui(Session& s)
      : s_(s), sim_out_open_(s.sim != nullptr), sim_err_open_(s.sim != nullptr), sim_truth_open_(s.sim != nullptr) {}

  // One pass; false once the console has finished.
  bool pass(std::mutex& lock) {
    enum { kKeyboard, kJoystick, kSimOut, kSimErr, kSimTruth, kCount };
    pollfd fds[kCount] = {};
    fds[kKeyboard] = {STDIN_FILENO, POLLIN, 0};
    fds[kJoystick] = {s_.joystick != nullptr ? s_.joystick->fd() : -1, POLLIN, 0};
    fds[kSimOut] = {sim_out_open_ ? s_.sim->out().fd() : -1, POLLIN, 0};
    fds[kSimErr] = {sim_err_open_ ? s_.sim->err().fd() : -1, POLLIN, 0};
    fds[kSimTruth] = {sim_truth_open_ ? s_.sim->truth().fd() : -1, POLLIN, 0};
    ::poll(fds, kCount, kUiPollMs);

    // Reading happens outside the lock: telling ESC from an arrow key waits a few ms.
    keys_.clear();
    for (Key key = s_.terminal.next_key(); key != kKeyNone; key = s_.terminal.next_key())
      keys_.push_back({key, monotonic_ms()});
    const bool joystick_read = s_.joystick != nullptr && fds[kJoystick].fd >= 0 && fds[kJoystick].revents != 0;
    const bool joystick_alive = joystick_read && s_.joystick->read();
    lines_.clear();
    read_sim(fds[kSimOut].revents != 0, s_.sim != nullptr ? &s_.sim->out() : nullptr, sim_out_open_, Severity::info);
    read_sim(fds[kSimErr].revents != 0, s_.sim != nullptr ? &s_.sim->err() : nullptr, sim_err_open_, Severity::warning);
    truth_.clear();
    if (fds[kSimTruth].revents != 0 && sim_truth_open_) truth_ = s_.sim->truth().read(sim_truth_open_);
    const uint32_t now = monotonic_ms();
    std::optional<std::string> sim_ended;
    if (s_.sim != nullptr && !sim_ended_ && now - last_child_check_ >= kChildCheckMs) {
      last_child_check_ = now;
      sim_ended = s_.sim->ended();
      sim_ended_ = sim_ended.has_value();
    }
    if (s_.joystick != nullptr && s_.joystick->fd() < 0 && now - last_joystick_retry_ >= kJoystickRetryMs) {
      last_joystick_retry_ = now;
      s_.joystick->reopen();
    }

    bool finished = false;
    bool redraw = false;
    {
      const std::lock_guard<std::mutex> hold(lock);
      Console& console = s_.console;
      for (const auto& [key, at] : keys_) console.key(key, at);
      if (joystick_read) joystick(joystick_alive, now);
      for (const auto& [severity, line] : lines_) console.note(severity, "sim: " + line);
      for (const std::string& line : truth_) console.truth_line(line);
      sim_commands_ = console.take_sim_commands();
      if (sim_ended) console.line_closed(*sim_ended, now);
      for (; signals_handled_ < exit_signals(); ++signals_handled_) {
        console.note(Severity::warning, "signal: exiting");
        console.request_exit(now);
      }
      finished = console.finished();
      // The plot moves: drawn more often, so a sample reaches the screen soon after it arrives.
      const uint32_t redraw_ms = console.screen() == Screen::plot ? kPlotRedrawMs : kRedrawMs;
      if (finished || now - last_draw_ >= redraw_ms) {
        last_draw_ = now;
        redraw = true;
        s_.cockpit.compose(console);
      }
    }
    if (s_.sim != nullptr) {
      for (const std::string& command : sim_commands_) s_.sim->send_truth_command(command);
    }
    if (redraw) s_.cockpit.show();  // may wait for the terminal; the link thread carries on
    return !finished;
  }

 private:
  void read_sim(bool readable, LineReader* reader, bool& open, Severity severity) {
    if (!readable || reader == nullptr || !open) return;
    for (std::string& line : reader->read(open)) lines_.push_back({severity, std::move(line)});
  }

  void joystick(bool alive, uint32_t now) {
    Console& console = s_.console;
    if (!alive) {
      console.joystick_lost(now);  // once: the console knows it is lost after that
      return;
    }
    JoystickReader& reader = s_.joystick->reader();
    // A device opened again counts as back once it has said where the stick is: one that opens
    // but delivers nothing (a half-gone USB device) is not a joystick.
    if (console.joystick_state() == JoystickState::lost) {
      if (!reader.position_known()) return;
      console.joystick_back(now);
    }
    if (reader.take_abort()) console.joystick_fire(now);
    console.joystick_moved(reader.sticks(), reader.position_known(), now);
  }

  Session& s_;
  bool sim_out_open_;
  bool sim_err_open_;
  bool sim_truth_open_;
  bool sim_ended_ = false;
  int signals_handled_ = 0;
  uint32_t last_draw_ = monotonic_ms() - kRedrawMs;
  uint32_t last_child_check_ = monotonic_ms();
  uint32_t last_joystick_retry_ = monotonic_ms();
  std::vector<std::pair<Key, uint32_t>> keys_;
  std::vector<std::pair<Severity, std::string>> lines_;
  std::vector<std::string> truth_;
  std::vector<std::string> sim_commands_;
};

}  // namespace

void run_main_loop(Session& s) {
  std::mutex lock;
  std::atomic<bool> stop{false};
  std::thread link([&] { run_link(s, lock, stop); });
  Ui ui(s);
  while (ui.pass(lock)) {
  }
  stop = true;
  link.join();
}

}  // namespace qrterm
