// qrfilter, as a function the tests can call: parses the arguments, designs the filter with the
// firmware's design code (qr/core/chain/butterworth_design.hpp) and prints JSON to `out`, or an
// error to `err`. Returns the process exit status: 0 ok (also for --help), 2 bad arguments.
#pragma once

#include <ostream>

namespace qr::tools {

int run_qrfilter(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace qr::tools
