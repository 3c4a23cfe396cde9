// The motor test screen's logic (docs/console.md "The motor test"), as Betaflight Configurator's
// motors tab does it: on the bench, propellers off, one engine at a time spins at a low level for
// the QR's 2 s (docs/safety.md rule 22), and the pilot says whether the rotor that turned is that
// engine's and turned its way, so a motor on the wrong output or turning the wrong way is found
// before the first flight. In the simulator the truth channel says which rotor turned and which
// way. Any key stops a spinning engine. With DShot ESCs (the QR reports their RPM) an engine
// turning the wrong way can be cured from here: its ESC's spin direction, set and saved
// (docs/safety.md rule 18).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <common/mode.hpp>
#include <common/nack_reason.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/key.hpp>

namespace qrterm {

// The level the console asks for: 10 % of full, half the QR's cap (wire::kMotorTestMaxLevel).
// Enough to see and hear a motor turn.
inline constexpr uint16_t kBenchLevel = 100;

// Where each rotor sits and which way it must turn, seen from above (docs/conventions.md), in
// engine order: engine n (1..4 on the screen, n - 1 on the wire) drives the rotor of row n - 1.
struct RotorPlace {
  const char* name;
  bool clockwise;
};
inline constexpr RotorPlace kRotorPlaces[4] = {{"front", true}, {"right", false}, {"back", true}, {"left", false}};

// A rotor turning slower than this, rad/s, did not turn (the bench level turns one at about 100).
inline constexpr double kTurningRadS = 10.0;

enum class BenchStep : uint8_t {
  props,      // asked first: are the propellers off?
  choose,     // 1-4 spins that engine
  spinning,   // the QR runs the test; any key stops it
  confirm,    // the pilot says whether the right rotor turned the right way
  direction,  // it did not: with DShot ESCs, its ESC's direction may be set
};

enum class EngineCheck : uint8_t { untested, confirmed, wrong };

class MotorBench {
 public:
  struct Hooks {
    std::function<bool(uint8_t engine, uint16_t level)> spin;  // the motor_test request (engine 0..3); false: not sent
    std::function<void()> stop;                                // a mode change to safe
    std::function<void(uint8_t engine, uint8_t direction)> direction;  // the esc_direction request
    std::function<bool()> dshot;                                       // the ESCs speak DShot (they answer)
    std::function<void()> leave;                                       // back to the cockpit
    std::function<void(Severity, const std::string&)> note;
  };

  explicit MotorBench(Hooks hooks) : hooks_(std::move(hooks)) {}

  // The screen opens: the propellers' question comes first, every time.
  void open();
  // A key on the bench's screen: every key but ESC and ^C, which still abort and exit.
  void key(Key key, uint32_t now_ms);
  // The QR's mode as telemetry reports it: the test's end is the QR's.
  void mode(wire::Mode mode);
  // The QR's answer to the motor test (none: ack), and no answer at all.
  void answer(wire::NackReason reason);
  void unanswered();
  // The simulator's truth line: each rotor's speed (SimulatorControls::rotors).
  void rotors(const std::array<double, 4>& rad_s);
  // Should the QR's end not be seen (telemetry lost), the console stops the test itself.
  void tick(uint32_t now_ms);

  BenchStep step() const { return step_; }
  // The engine tested last (0..3).
  uint8_t engine() const { return engine_; }
  EngineCheck check(uint8_t engine) const { return checks_[engine]; }
  // What the simulator saw the last test turn ("sim: rotor 2 (right) turned counter-clockwise"),
  // empty without a simulator's truth.
  std::string simulator_saw() const;
  // The screen: a line per engine, then what to do now.
  std::vector<std::string> lines() const;

 private:
  void spin(uint8_t engine, uint32_t now_ms);
  void stop();
  void confirm(Key key);
  void set_direction(Key key);
  std::string prompt() const;

  Hooks hooks_;
  BenchStep step_ = BenchStep::props;
  uint8_t engine_ = 0;
  std::array<EngineCheck, 4> checks_{};
  bool test_seen_ = false;  // telemetry has shown the QR in its motor test
  uint32_t started_ms_ = 0;
  // The simulator's rotors during the test: each one's fastest speed, signed.
  std::optional<std::array<double, 4>> peak_;
};

}  // namespace qrterm
