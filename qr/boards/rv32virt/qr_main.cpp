// The flight firmware for the devboard: build/rv32/qr/qr.elf.
#include <qr/boards/rv32virt/firmware.hpp>
#include <qr/core/chain/flight_chain.hpp>

int main() { return rv32virt::run_firmware<qr::FixedChain>(); }
