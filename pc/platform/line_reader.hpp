// Lines from a non-blocking pipe (the simulator's stdout and stderr), whole lines only: a line
// cut by a read waits for its end.
#pragma once

#include <string>
#include <vector>

namespace qrterm {

class LineReader {
 public:
  explicit LineReader(int fd) : fd_(fd) {}

  // Whole lines read so far; `open` turns false at end of file (then the last partial line
  // comes out too).
  std::vector<std::string> read(bool& open);
  int fd() const { return fd_; }

 private:
  int fd_;
  std::string partial_;
};

}  // namespace qrterm
