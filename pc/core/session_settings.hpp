// Settings that do not trap (issue 36): the parameter file keeps what a session set, and a value
// that made sense in one session can stop the next: `pilot = 1` saved from a session with the
// simulator's radio left the next plain start unable to arm from any key. At start the console
// names each saved value that cannot work (or will surprise) in this session, with its fix; at exit
// it names how to undo each change the session saved.
#pragma once

#include <string>
#include <vector>

#include <common/parameter_table.hpp>

namespace qrterm {

// What the console flies this session, as far as a saved value depends on it.
struct SessionKind {
  bool simulator = false;        // the console started the simulator (not --port)
  bool simulator_radio = false;  // and gave it a radio (--sim-arg --rc)
};

// The simulator's arguments give it a radio (qrsim --rc crsf, docs/simulator.md section 5).
bool simulator_has_radio(const std::vector<std::string>& simulator_arguments);
// They have it fly the devboard (qrsim --devboard [ELF], docs/devboard.md).
bool simulator_flies_devboard(const std::vector<std::string>& simulator_arguments);

// One line per saved value that cannot work (or will surprise) in this session: the value, why,
// and the fix. Empty when every value is fine.
std::vector<std::string> settings_that_trap(const wire::ParameterValues& saved, const SessionKind& session);

// One line per parameter this session changed, with the line that undoes it:
// "roll_pitch_p1 5.5 -> 5.75   undo: roll_pitch_p1 = 5.5". Empty when nothing changed.
std::vector<std::string> undo_lines(const wire::ParameterValues& before, const wire::ParameterValues& after);

}  // namespace qrterm
