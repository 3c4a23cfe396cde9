// The console's plumbing on real ptys and child processes: opening a port (and the clear
// messages when it cannot be), and starting the simulator (and the clear messages when it fails).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <pc/core/log_retention.hpp>
#include <pc/core/recordings.hpp>
#include <pc/platform/log_folder.hpp>
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

namespace {

// A fresh folder under the test's temporary directory, removed when the test ends.
struct TemporaryFolder {
  std::string path;
  TemporaryFolder() {
    char name[] = "/tmp/qrterm-logs.XXXXXX";
    path = ::mkdtemp(name);
  }
  ~TemporaryFolder() { std::filesystem::remove_all(path); }
};

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

// A week of flying left a folder per start under ./logs: the newest 20 stay (the session's own
// among them), the oldest go with their files, and a folder the console did not name stays.
TEST(LogRetention, TheNewestSessionFoldersStayTheOldestGo) {
  EXPECT_TRUE(qrterm::is_session_folder_name("20250131-142502"));
  EXPECT_FALSE(qrterm::is_session_folder_name("my-flight"));
  EXPECT_FALSE(qrterm::is_session_folder_name("20250131-14250x"));
  const std::vector<std::string> names{"20250103-100000", "20250101-100000", "keep-me", "20250102-100000",
                                       "20250104-100000"};
  EXPECT_EQ(qrterm::log_folders_to_remove(names, "20250104-100000", 2),
            (std::vector<std::string>{"20250101-100000", "20250102-100000"}));
  EXPECT_EQ(qrterm::log_folders_to_remove(names, "20250101-100000", 1),
            (std::vector<std::string>{"20250102-100000", "20250103-100000", "20250104-100000"}))
      << "the current folder stays even when it is the oldest (a clock set back)";
  EXPECT_TRUE(qrterm::log_folders_to_remove(names, "20250104-100000", 0).empty()) << "0 keeps every folder";
  EXPECT_TRUE(qrterm::log_folders_to_remove(names, "20250104-100000", 20).empty());

  TemporaryFolder logs;
  for (int day = 1; day <= 23; ++day) {
    const std::string folder = logs.path + "/202501" + (day < 10 ? "0" : "") + std::to_string(day) + "-120000";
    qrterm::make_folders(folder);
    *qrterm::open_in(folder, "console.log") << "a session\n";
  }
  qrterm::make_folders(logs.path + "/by-hand");
  const std::string session = logs.path + "/20250123-120000";
  std::string failed;
  EXPECT_EQ(qrterm::remove_old_log_folders(session, qrterm::kLogFoldersKept, failed), 3u);
  EXPECT_EQ(failed, "");
  std::vector<std::string> left = qrterm::folders_in(logs.path);
  std::sort(left.begin(), left.end());
  ASSERT_EQ(left.size(), qrterm::kLogFoldersKept + 1);
  EXPECT_EQ(left.front(), "20250104-120000") << "the three oldest went";
  EXPECT_EQ(left.back(), "by-hand");
  EXPECT_TRUE(std::filesystem::exists(session + "/console.log"));
}

// rx.hex at its part size starts again: the full part is rx.hex.1 (replacing the one before),
// so a session keeps two parts at most, the newest bytes always in rx.hex.
TEST(Platform, RxHexStartsAgainKeepingOnePreviousFile) {
  TemporaryFolder folder;
  *qrterm::open_in(folder.path, "rx.hex") << "first\n";
  auto second = qrterm::start_again_in(folder.path, "rx.hex", qrterm::kRxHexPrevious);
  ASSERT_NE(second, nullptr);
  *second << "second\n";
  second.reset();
  EXPECT_EQ(read_all(folder.path + "/rx.hex.1"), "first\n");
  auto third = qrterm::start_again_in(folder.path, "rx.hex", qrterm::kRxHexPrevious);
  *third << "third\n";
  third.reset();
  EXPECT_EQ(read_all(folder.path + "/rx.hex.1"), "second\n") << "one previous file, the newer";
  EXPECT_EQ(read_all(folder.path + "/rx.hex"), "third\n");
  EXPECT_EQ(qrterm::folders_in(folder.path).size(), 0u);
}
