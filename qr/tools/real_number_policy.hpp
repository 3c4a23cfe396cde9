// The floating-point number policy moved to qr/host/real_number_policy.hpp, below both host
// programs (qrsim and the tools). This name stays for the RV32 firmware bench
// (tests/devboard/firmware_bench.cpp) until it includes the new one.
#pragma once

#include <qr/host/real_number_policy.hpp>
