// The simulator as a child process: `qrsim --serve` runs the firmware in a simulated world and
// offers the QR's serial line on a pty, naming it on its first line of output
// ("qrsim: serial on /dev/pts/N"). The console starts it, reads that line, and then talks to the
// pty exactly as to a real QR; the child's further output comes through pipes into the log, so it
// never scribbles over the screen.
#pragma once

#include <stdint.h>
#include <sys/types.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <pc/platform/line_reader.hpp>

namespace qrterm {

struct SimError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class SimProcess {
 public:
  // Starts the program and waits (up to timeout_ms) for it to name its serial line. Throws
  // SimError with what went wrong: not found, not executable, ended early (with its output),
  // or silent.
  SimProcess(const std::string& program, const std::vector<std::string>& arguments, uint32_t timeout_ms);
  ~SimProcess();
  SimProcess(const SimProcess&) = delete;
  SimProcess& operator=(const SimProcess&) = delete;

  pid_t pid() const { return pid_; }
  const std::string& serial_path() const { return serial_path_; }
  // Output the simulator printed while starting, besides the serial line.
  const std::vector<std::string>& early_output() const { return early_output_; }

  LineReader& out() { return out_; }
  LineReader& err() { return err_; }
  // The simulator's truth channel (qrsim --truth-fd, docs/simulator.md): truth lines in, command
  // lines out. The child has it as descriptor kTruthFd; pass "--truth-fd 3" to qrsim.
  LineReader& truth() { return truth_; }
  void send_truth_command(const std::string& line);
  static constexpr int kTruthFd = 3;

  // Once the child has ended: how ("simulator exited with status 1"); empty while it runs.
  std::optional<std::string> ended();

  // Gives it `grace_ms` to end by itself (it stops after the exit handshake), then SIGTERM, then
  // SIGKILL. Returns at most about grace_ms + 1 s later.
  void stop(uint32_t grace_ms);

 private:
  // The child, with its stdout, stderr and truth channel on our ends.
  void spawn(const std::string& program, const std::vector<std::string>& arguments);
  // Reads its output until it names its serial line; throws when it ends or stays silent.
  void wait_for_serial_line(const std::string& program, uint32_t timeout_ms);
  void close_channels();
  bool wait_ms(uint32_t ms);

  pid_t pid_ = -1;
  bool reaped_ = false;
  std::string status_text_;
  std::string serial_path_;
  std::vector<std::string> early_output_;
  LineReader out_{-1};
  LineReader err_{-1};
  LineReader truth_{-1};
};

// "exited with status 1", "killed by signal 9 (Killed)".
std::string describe_wait_status(int status);

}  // namespace qrterm
