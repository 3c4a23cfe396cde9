// The motor test's screen (docs/console.md "The motor test"): below the status rows, each engine
// with its command now, its rotor, the way that rotor must turn and what the pilot found; what the
// simulator saw turn; what to do now. The console's log follows (the cockpit draws it).
#include <pc/ui/screen_draw.hpp>
#include <pc/ui/screens.hpp>
#include <pc/ui/terminal.hpp>

namespace qrterm {

int draw_motor_test_screen(const Console& console, int top, int width) {
  const MotorBench& bench = console.motor_bench();
  const TelemetryModel& t = console.telemetry();
  put(top, 0, "MOTOR TEST", 0, A_BOLD);
  put(top, 11, "propellers OFF; one engine at 10 % for 2 s; any key stops it", kWarning, A_BOLD);
  put(top + 1, 0, text("%-4s  %-8s  %-5s  %-17s  %s", "now", "engine", "rotor", "must turn", "found"), 0, A_UNDERLINE);
  const std::vector<std::string> lines = bench.lines();
  for (int i = 0; i < 4; ++i) {
    const int row = top + 2 + i;
    put(row, 0, t.engines ? text("%4d", t.engines->engine[i]) : std::string("   ?"), t.engines ? 0 : kDim);
    const EngineCheck check = bench.check(static_cast<uint8_t>(i));
    put(row, 6, lines[static_cast<size_t>(i)],
        check == EngineCheck::wrong       ? kError
        : check == EngineCheck::confirmed ? kInfo
                                          : 0);
  }
  put(top + 6, 0, lines[4], kQr);
  const bool spinning = bench.step() == BenchStep::spinning;
  put(top + 7, 0, lines[5].substr(0, static_cast<size_t>(width)), spinning ? kAlarm : kTitle, A_BOLD);
  return top + 9;
}

}  // namespace qrterm
