// The console's plumbing on real ptys and child processes: opening a port (and the clear
// messages when it cannot be), and starting the simulator (and the clear messages when it fails).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <pc/platform/serial_port.hpp>
#include <pc/platform/sim_process.hpp>

namespace {

using qrterm::SerialError;
using qrterm::SerialPort;
using qrterm::SimError;
using qrterm::SimProcess;

class Pty {
 public:
  Pty() {
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
    EXPECT_GE(master_, 0);
    ::grantpt(master_);
    ::unlockpt(master_);
  }
  ~Pty() { ::close(master_); }
  std::string slave() const { return ::ptsname(master_); }
  int master() const { return master_; }

 private:
  int master_ = -1;
};

std::string error_of(const std::string& path, uint32_t baud = 115200) {
  try {
    SerialPort port(path, baud);
  } catch (const SerialError& e) {
    return e.what();
  }
  return "";
}

TEST(Console, SerialPortOnAPtyCarriesBytesBothWays) {
  Pty pty;
  SerialPort port(pty.slave(), 115200);
  std::vector<uint8_t> out{0x4D, 0x0D, 0x0A, 0x00, 0xFF};  // CR, LF and NUL must pass untouched: raw mode
  std::string why;
  ASSERT_EQ(port.write_some(out, why), SerialPort::Io::ok);
  EXPECT_TRUE(out.empty());
  uint8_t got[16] = {};
  usleep(20000);
  ASSERT_EQ(::read(pty.master(), got, sizeof got), 5);
  EXPECT_EQ(got[1], 0x0D);
  EXPECT_EQ(got[2], 0x0A);
  const uint8_t back[] = {0x0D, 0x03, 0x7F};  // no ^C signal, no erase
  ASSERT_EQ(::write(pty.master(), back, sizeof back), 3);
  usleep(20000);
  std::vector<uint8_t> in;
  ASSERT_EQ(port.read_available(in, why), SerialPort::Io::ok);
  EXPECT_EQ(in, std::vector<uint8_t>(back, back + 3));
}

TEST(Console, SerialPortWhoseOtherEndClosesSaysSo) {
  auto pty = std::make_unique<Pty>();
  SerialPort port(pty->slave(), 115200);
  pty.reset();
  std::vector<uint8_t> in;
  std::string why;
  EXPECT_EQ(port.read_available(in, why), SerialPort::Io::closed);
  EXPECT_FALSE(why.empty());
}

TEST(Console, SerialPortErrorsAreClear) {
  EXPECT_NE(
      error_of("/dev/ttyQR-none").find("cannot open /dev/ttyQR-none: No such file or directory (is the QR plugged in?"),
      std::string::npos)
      << error_of("/dev/ttyQR-none");
  EXPECT_NE(error_of("/dev/null").find("/dev/null is not a serial device"), std::string::npos) << error_of("/dev/null");
  Pty pty;
  EXPECT_NE(error_of(pty.slave(), 12345).find("baud rate 12345 is not supported (9600,"), std::string::npos);
}

TEST(Console, SerialPortInUseIsBusy) {
  Pty pty;
  SerialPort first(pty.slave(), 115200);
  const std::string error = error_of(pty.slave());
  EXPECT_NE(error.find("is busy"), std::string::npos) << error;
}

TEST(Console, SimulatorNamesItsSerialLine) {
  SimProcess sim("/bin/sh", {"-c", "echo starting; echo 'qrsim: serial on /dev/pts/77'; sleep 5"}, 5000);
  EXPECT_EQ(sim.serial_path(), "/dev/pts/77");
  EXPECT_EQ(sim.early_output(), std::vector<std::string>{"starting"});
  EXPECT_FALSE(sim.ended());
  sim.stop(0);
  ASSERT_TRUE(sim.ended());
  EXPECT_EQ(*sim.ended(), "simulator killed by signal 15 (Terminated)");
}

TEST(Console, SimulatorThatDiesEarlySaysHowWithItsOutput) {
  try {
    SimProcess sim("/bin/sh", {"-c", "echo 'no world file' >&2; exit 3"}, 5000);
    FAIL() << "started";
  } catch (const SimError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("simulator exited with status 3 before naming its serial line"), std::string::npos)
        << message;
    EXPECT_NE(message.find("no world file"), std::string::npos) << message;
  }
}

TEST(Console, SimulatorMissingOrSilentIsAClearError) {
  try {
    SimProcess sim("/nonexistent/qrsim", {}, 1000);
    FAIL();
  } catch (const SimError& e) {
    EXPECT_NE(std::string(e.what()).find("no simulator at /nonexistent/qrsim (build it"), std::string::npos)
        << e.what();
  }
  try {
    SimProcess sim("/bin/sh", {"-c", "sleep 5"}, 300);
    FAIL();
  } catch (const SimError& e) {
    EXPECT_NE(std::string(e.what()).find("did not name its serial line within 0.3 s"), std::string::npos) << e.what();
  }
}

}  // namespace
