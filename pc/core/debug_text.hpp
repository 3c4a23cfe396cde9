// The QR's debug text arrives in pieces of up to 9 characters (wire::DebugText); this puts them
// back into lines, broken at '\n'. A piece lost on the way costs at most 9 characters of a line.
#pragma once

#include <stddef.h>

#include <string>
#include <vector>

#include <common/replies.hpp>

namespace qrterm {

class DebugTextAssembler {
 public:
  // Adds a piece; returns the lines it completed (usually none or one).
  std::vector<std::string> add(const wire::DebugText& piece);

 private:
  // A line never ends (a QR printing without '\n'): it is shown in pieces of this length.
  static constexpr size_t kMaxLine = 200;

  std::string line_;
};

}  // namespace qrterm
