// The console and a FakeQr wired back to back on a scripted clock, 1 ms a step: what one sends
// the other receives in the same millisecond, unless the line is cut.
#pragma once

#include <stdint.h>

#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <pc/core/console.hpp>

#include "fake_qr.hpp"

namespace qrterm_test {

// A file the console opens in its log folder; what was written is kept when it is closed. With
// `room` it is on a disk that fills up after that many bytes: then every write fails.
class CapturedFile : public std::ostream {
 public:
  explicit CapturedFile(std::string& sink, size_t room = SIZE_MAX)
      : std::ostream(&buffer_), buffer_(room), sink_(sink) {}
  ~CapturedFile() override { sink_ = buffer_.text; }

 private:
  struct Disk : std::streambuf {
    explicit Disk(size_t room) : room(room) {}
    int_type overflow(int_type c) override {
      if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
      if (text.size() >= room) return traits_type::eof();  // No space left on device
      text.push_back(traits_type::to_char_type(c));
      return c;
    }
    size_t room;
    std::string text;
  };
  Disk buffer_;
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
      if (folder_read_only) return nullptr;
      return std::make_unique<CapturedFile>(written[name], disk_room);
    };
    f.rename = [this](const std::string& from, const std::string& to) {
      if (folder_read_only) return false;
      if (written.count(from) != 0) {  // the session files are the bench's own streams
        written[to] = written[from];
        written.erase(from);
      }
      renamed.emplace_back(from, to);
      return true;
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
  std::vector<std::pair<std::string, std::string>> renamed;
  size_t disk_room = SIZE_MAX;  // bytes a new file may take before the disk is full
  bool folder_read_only = false;
  qrterm::Console console;
  FakeQr qr;
};

}  // namespace qrterm_test
