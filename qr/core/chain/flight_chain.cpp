// The flight instantiation, compiled once into qr_chain: every member of FixedChain is built here
// under the freestanding flags, on the host and for RV32 alike, so code that only the flight
// number types reach cannot hide from either compiler.
#include <qr/core/chain/flight_chain.hpp>

template class qr::FlightChain<qr::chain::FixedNumbers>;
