// The console and a FakeQr wired back to back on a scripted clock, 1 ms a step: what one sends
// the other receives in the same millisecond, unless the line is cut.
#pragma once

#include <stdint.h>

#include <map>
#include <memory>
#include <sstream>
#include <string>

#include <pc/core/console.hpp>

#include "fake_qr.hpp"

namespace qrterm_test {

// A file the console opens in its log folder; what was written is kept when it is closed.
class CapturedFile : public std::ostringstream {
 public:
  explicit CapturedFile(std::string& sink) : sink_(sink) {}
  ~CapturedFile() override { sink_ = str(); }

 private:
  std::string& sink_;
};

struct Bench {
  explicit Bench(const qrterm::Console::Setup& setup = {}, uint32_t start_ms = 5000)
      : now(start_ms), console(log, files(), setup, start_ms), qr(start_ms) {}

  qrterm::ConsoleFiles files() {
    qrterm::ConsoleFiles f;
    f.rx_hex = &hex;
    f.telemetry_csv = &telemetry_csv;
    f.open = [this](const std::string& name) -> std::unique_ptr<std::ostream> {
      return std::make_unique<CapturedFile>(written[name]);
    };
    return f;
  }

  // Runs both ends for `ms` milliseconds.
  void run(uint32_t ms) {
    for (uint32_t i = 0; i < ms; ++i) {
      ++now;
      console.tick(now);
      std::vector<uint8_t>& up = console.output();
      if (!cut) qr.receive(up, now);
      up.clear();
      qr.tick(now);
      const std::vector<uint8_t> down = qr.take_output();
      if (!cut) console.receive(down.data(), down.size(), now);
    }
  }

  // Runs until the condition holds, at most `limit_ms`; returns whether it did.
  template <class Condition>
  bool run_until(Condition condition, uint32_t limit_ms) {
    for (uint32_t i = 0; i < limit_ms; ++i) {
      if (condition()) return true;
      run(1);
    }
    return condition();
  }

  void key(qrterm::Key key) { console.key(key, now); }
  void keys(const std::string& typed) {
    for (char c : typed) key(c);
  }

  // Connects and waits for the parameter upload to finish.
  void connect() { run(600); }

  bool logged(const std::string& fragment) const { return log.find_last(fragment) != nullptr; }

  uint32_t now;
  bool cut = false;
  qrterm::ConsoleLog log;
  std::ostringstream hex;
  std::ostringstream telemetry_csv;
  std::map<std::string, std::string> written;
  qrterm::Console console;
  FakeQr qr;
};

}  // namespace qrterm_test
