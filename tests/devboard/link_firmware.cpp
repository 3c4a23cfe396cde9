// The flight context with a scripted signal chain on the devboard: exercises the board's kick,
// interrupt-driven receive and bounded transmit through the real link, before the signal chain.
#include <qr/boards/rv32virt/firmware.hpp>

#include "../qr/scripted_chain.hpp"

int main() { return rv32virt::run_firmware<qr::test::ScriptedChain>(); }
