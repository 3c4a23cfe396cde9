// What the log says about the QR's answers to the console's requests: the name of each request,
// the line an accepted one is worth, and a refusal's reason as the pilot reads it. Mode changes,
// log downloads and the exit have more to say and say it where they are handled.
#pragma once

#include <string>

#include <common/messages.hpp>

namespace qrterm {

// "mode change", "log start": as in "no answer from the QR to the log start request".
const char* request_what(wire::MessageType type);
// The line an accepted request is worth ("QR logs stopped"); null: nothing worth a line.
const char* request_accepted(wire::MessageType type);
// A nack's reason: "not neutral", "needs calibration"; "refused" for a reason this console
// does not know.
std::string reason_text(wire::NackReason reason);

}  // namespace qrterm
