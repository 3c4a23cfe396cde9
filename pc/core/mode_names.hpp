// Modes as the pilot reads them on the screen and in the log: the shared mode table's words.
#pragma once

#include <common/mode.hpp>

namespace qrterm {

using wire::mode_name;

// Modes the QR flies in (docs/safety.md): the engines may be running.
inline bool is_flight_mode(wire::Mode mode) { return wire::flies(mode); }

}  // namespace qrterm
