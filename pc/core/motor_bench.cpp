#include <pc/core/motor_bench.hpp>

#include <cmath>
#include <cstdio>
#include <iterator>

#include <pc/core/request_texts.hpp>

namespace qrterm {
namespace {

// The QR ends its test after 2 s; the console stops it itself should that end not be seen by then
// (a request resent for its full second, then the test, then a telemetry period or two).
constexpr uint32_t kBenchGiveUpMs = 3500;

const char* way(bool clockwise) { return clockwise ? "clockwise" : "counter-clockwise"; }

std::string rotor_name(size_t rotor) {
  return "rotor " + std::to_string(rotor + 1) + " (" + kRotorPlaces[rotor].name + ")";
}

const char* check_text(EngineCheck check) {
  switch (check) {
    case EngineCheck::untested: return "not tested";
    case EngineCheck::confirmed: return "confirmed";
    case EngineCheck::wrong: return "WRONG: check its output and direction";
  }
  return "";
}

}  // namespace

void MotorBench::open() {
  step_ = BenchStep::props;
  peak_.reset();
}

void MotorBench::key(Key key, uint32_t now_ms) {
  switch (step_) {
    case BenchStep::props:
      if (key == 'y' || key == 'Y') {
        step_ = BenchStep::choose;
      } else {
        hooks_.note(Severity::info, "motor test left: spin engines only with the propellers off");
        hooks_.leave();
      }
      return;
    case BenchStep::choose:
      if (key >= '1' && key <= '4') return spin(static_cast<uint8_t>(key - '1'), now_ms);
      if (key == 'q' || key == 'Q' || key == kKeyTab) return hooks_.leave();
      hooks_.note(Severity::warning, "motor test: 1-4 spins that engine, q leaves");
      return;
    case BenchStep::spinning: return stop();
    case BenchStep::confirm: return confirm(key);
    case BenchStep::direction: return set_direction(key);
  }
}

void MotorBench::spin(uint8_t engine, uint32_t now_ms) {
  engine_ = engine;
  test_seen_ = false;
  started_ms_ = now_ms;
  peak_.reset();
  if (hooks_.spin(engine, kBenchLevel)) step_ = BenchStep::spinning;
}

void MotorBench::stop() {
  hooks_.stop();
  step_ = BenchStep::confirm;
}

void MotorBench::confirm(Key key) {
  if (key == 'y' || key == 'Y') {
    checks_[engine_] = EngineCheck::confirmed;
  } else if (key == 'n' || key == 'N') {
    checks_[engine_] = EngineCheck::wrong;
    if (hooks_.dshot()) {
      step_ = BenchStep::direction;
      return;
    }
    hooks_.note(Severity::warning, "engine " + std::to_string(engine_ + 1) +
                                       ": the wrong rotor or the wrong way; fix its output, or swap two of its motor's "
                                       "wires");
  } else {
    return;  // the question stands
  }
  step_ = BenchStep::choose;
}

void MotorBench::set_direction(Key key) {
  step_ = BenchStep::choose;
  if (key != '1' && key != '2') return;
  const auto direction = static_cast<uint8_t>(key - '0');
  hooks_.direction(engine_, direction);
  hooks_.note(Severity::info, "engine " + std::to_string(engine_ + 1) + ": its ESC to spin direction " +
                                  std::to_string(direction) + (direction == 1 ? " (normal)" : " (reversed)") +
                                  ", saved; spin it again to see");
}

void MotorBench::mode(wire::Mode mode) {
  if (step_ != BenchStep::spinning) return;
  if (mode == wire::Mode::motor_test) {
    test_seen_ = true;
  } else if (test_seen_) {
    step_ = BenchStep::confirm;  // the QR ended its test
  }
}

void MotorBench::answer(wire::NackReason reason) {
  if (step_ != BenchStep::spinning || reason == wire::NackReason::none) return;
  hooks_.note(Severity::warning, "QR refused the motor test: " + reason_text(reason));
  step_ = BenchStep::choose;
}

void MotorBench::unanswered() {
  if (step_ != BenchStep::spinning) return;
  hooks_.note(Severity::error, "no answer from the QR to the motor test");
  step_ = BenchStep::choose;
}

void MotorBench::rotors(const std::array<double, 4>& rad_s) {
  if (step_ != BenchStep::spinning) return;
  if (!peak_) peak_ = std::array<double, 4>{};
  for (size_t i = 0; i < rad_s.size(); ++i) {
    if (std::fabs(rad_s[i]) > std::fabs((*peak_)[i])) (*peak_)[i] = rad_s[i];
  }
}

void MotorBench::tick(uint32_t now_ms) {
  if (step_ != BenchStep::spinning || now_ms - started_ms_ < kBenchGiveUpMs) return;
  hooks_.note(Severity::warning, "motor test: the QR's end was not seen; stopped by the console");
  stop();
}

std::string MotorBench::simulator_saw() const {
  if (!peak_) return "";
  size_t fastest = 0;
  for (size_t i = 1; i < peak_->size(); ++i) {
    if (std::fabs((*peak_)[i]) > std::fabs((*peak_)[fastest])) fastest = i;
  }
  const double speed = (*peak_)[fastest];
  if (std::fabs(speed) < kTurningRadS) return "sim: no rotor turned";
  const bool clockwise = speed > 0;
  std::string saw = "sim: " + rotor_name(fastest) + " turned " + way(clockwise);
  // At most 80 columns: the engine's own rotor and way are on its row above.
  if (fastest != engine_) {
    saw += ": the wrong rotor for engine " + std::to_string(engine_ + 1);
  } else if (clockwise != kRotorPlaces[engine_].clockwise) {
    saw += ": the wrong way";
  } else {
    saw += ", as engine " + std::to_string(engine_ + 1) + " must";
  }
  return saw;
}

std::string MotorBench::prompt() const {
  const std::string engine = "engine " + std::to_string(engine_ + 1);
  const RotorPlace& own = kRotorPlaces[engine_];
  switch (step_) {
    case BenchStep::props: return "Are the propellers OFF?  y: yes, they are off   any other key: back to the cockpit";
    case BenchStep::choose: return "1-4: spin that engine for 2 s   q: back to the cockpit";
    case BenchStep::spinning: return engine + " (" + own.name + ") spinning at 10 %   ANY KEY STOPS IT";
    case BenchStep::confirm:
      return "Did the " + std::string(own.name) + " rotor turn, " + way(own.clockwise) +
             " seen from above?  y: yes   n: no";
    case BenchStep::direction: return "The wrong way? Its DShot ESC, saved: 1 normal  2 reversed   other key: leave it";
  }
  return "";
}

std::vector<std::string> MotorBench::lines() const {
  std::vector<std::string> out;
  for (size_t i = 0; i < std::size(kRotorPlaces); ++i) {
    char row[96];
    std::snprintf(row, sizeof row, "engine %zu  %-5s  %-17s  %s", i + 1, kRotorPlaces[i].name,
                  way(kRotorPlaces[i].clockwise), check_text(checks_[i]));
    out.emplace_back(row);
  }
  out.push_back(simulator_saw());
  out.push_back(prompt());
  return out;
}

}  // namespace qrterm
