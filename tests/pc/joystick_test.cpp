// The joystick reader fed with struct js_event records through a pipe, as the driver would
// deliver them, and the joystick map file.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <pc/core/joystick_map.hpp>
#include <pc/core/joystick_reader.hpp>

namespace {

using qrterm::JoystickMap;
using qrterm::JoystickReader;

class Pipe {
 public:
  Pipe() {
    int fds[2];
    EXPECT_EQ(::pipe2(fds, O_NONBLOCK), 0);
    read_ = fds[0];
    write_ = fds[1];
  }
  ~Pipe() {
    ::close(read_);
    close_writer();
  }
  void send(uint8_t type, uint8_t number, int16_t value, uint32_t time = 0) {
    const js_event event{time, value, type, number};
    ASSERT_EQ(::write(write_, &event, sizeof event), static_cast<ssize_t>(sizeof event));
  }
  void send_bytes(const void* data, size_t count) {
    ASSERT_EQ(::write(write_, data, count), static_cast<ssize_t>(count));
  }
  void close_writer() {
    if (write_ >= 0) ::close(write_);
    write_ = -1;
  }
  int fd() const { return read_; }

 private:
  int read_ = -1;
  int write_ = -1;
};

// What the driver sends right after open: every axis and button, flagged INIT.
void send_initial_state(Pipe& pipe, int16_t throttle = 32767) {
  for (uint8_t axis = 0; axis < 4; ++axis) pipe.send(JS_EVENT_AXIS | JS_EVENT_INIT, axis, axis == 3 ? throttle : 0);
  for (uint8_t button = 0; button < 4; ++button) pipe.send(JS_EVENT_BUTTON | JS_EVENT_INIT, button, 0);
}

TEST(Joystick, ReadsAxesThroughTheMap) {
  Pipe pipe;
  JoystickReader reader{JoystickMap{}};
  EXPECT_FALSE(reader.position_known());
  send_initial_state(pipe);
  EXPECT_EQ(reader.read_from(pipe.fd()), JoystickReader::ReadResult::ok);
  EXPECT_TRUE(reader.position_known());
  EXPECT_EQ(reader.sticks(), qrterm::Sticks{}) << "throttle back (+32767, inverted) is lift 0";
  pipe.send(JS_EVENT_AXIS, 0, 32767);   // stick right
  pipe.send(JS_EVENT_AXIS, 1, -32767);  // stick forward
  pipe.send(JS_EVENT_AXIS, 2, 16384);   // twist right, half
  pipe.send(JS_EVENT_AXIS, 3, -32767);  // throttle fully forward
  reader.read_from(pipe.fd());
  const qrterm::Sticks s = reader.sticks();
  EXPECT_EQ(s.roll, 1000);
  EXPECT_EQ(s.pitch, -1000) << "forward is nose down";
  EXPECT_NEAR(s.yaw, 473, 2) << "half deflection, less the 5 % deadband, stretched";
  EXPECT_EQ(s.lift, 1000);
}

TEST(Joystick, DeadbandAroundTheCentreAndAtTheThrottlesLowEnd) {
  JoystickMap map;
  map.deadband_permille = 50;
  EXPECT_EQ(map.stick(map.roll, 1600), 0);  // 48 per mille
  EXPECT_EQ(map.stick(map.roll, -1600), 0);
  EXPECT_GT(map.stick(map.roll, 1800), 0);
  EXPECT_LT(map.stick(map.roll, 1800), 10) << "starts from zero at the band's edge, no jump";
  EXPECT_EQ(map.lift_of(32767 - 3000), 0) << "a throttle resting a little above its stop is closed";
  EXPECT_EQ(map.lift_of(-32767), 1000);
  map.deadband_permille = 0;
  EXPECT_EQ(map.stick(map.roll, 33), 1);
  EXPECT_EQ(map.stick(map.roll, -32768), -1000) << "the driver's -32768 is clamped";
}

TEST(Joystick, ThrottleNotYetReportedCountsAsClosed) {
  JoystickReader reader{JoystickMap{}};
  EXPECT_EQ(reader.sticks().lift, 0);
}

TEST(Joystick, FireButtonPressIsOneAbortAndTheStateAtOpenIsNone) {
  Pipe pipe;
  JoystickReader reader{JoystickMap{}};
  pipe.send(JS_EVENT_BUTTON | JS_EVENT_INIT, 0, 1);  // held while the device was opened
  reader.read_from(pipe.fd());
  EXPECT_FALSE(reader.take_abort());
  pipe.send(JS_EVENT_BUTTON, 0, 0);
  pipe.send(JS_EVENT_BUTTON, 1, 1);  // another button
  pipe.send(JS_EVENT_BUTTON, 0, 1);
  reader.read_from(pipe.fd());
  EXPECT_TRUE(reader.take_abort());
  EXPECT_FALSE(reader.take_abort()) << "an edge, taken once";
}

TEST(Joystick, AbortButtonComesFromTheMap) {
  Pipe pipe;
  JoystickMap map;
  map.abort_button = 3;
  JoystickReader reader{map};
  pipe.send(JS_EVENT_BUTTON, 0, 1);
  reader.read_from(pipe.fd());
  EXPECT_FALSE(reader.take_abort());
  pipe.send(JS_EVENT_BUTTON, 3, 1);
  reader.read_from(pipe.fd());
  EXPECT_TRUE(reader.take_abort());
}

TEST(Joystick, RecordCutAcrossReadsIsPutBackTogether) {
  Pipe pipe;
  JoystickReader reader{JoystickMap{}};
  const js_event event{0, 32767, JS_EVENT_AXIS, 0};
  const uint8_t* bytes = reinterpret_cast<const uint8_t*>(&event);
  pipe.send_bytes(bytes, 3);
  reader.read_from(pipe.fd());
  EXPECT_EQ(reader.sticks().roll, 0);
  pipe.send_bytes(bytes + 3, sizeof event - 3);
  reader.read_from(pipe.fd());
  EXPECT_EQ(reader.sticks().roll, 1000);
}

TEST(Joystick, EndOfTheStreamMeansTheJoystickIsGone) {
  Pipe pipe;
  JoystickReader reader{JoystickMap{}};
  send_initial_state(pipe);
  EXPECT_EQ(reader.read_from(pipe.fd()), JoystickReader::ReadResult::ok);
  EXPECT_EQ(reader.read_from(pipe.fd()), JoystickReader::ReadResult::ok) << "nothing to read is not gone";
  pipe.close_writer();
  EXPECT_EQ(reader.read_from(pipe.fd()), JoystickReader::ReadResult::lost);
}

TEST(Joystick, MapFileSetsAxesInversionDeadbandAndButton) {
  const qrterm::JoystickMapFile file = qrterm::parse_joystick_map(
      "# my stick\nlift_axis = 2\nlift_invert = no\nyaw_axis = 3\nroll_invert = yes\nabort_button = 1\ndeadband = "
      "80\n");
  ASSERT_TRUE(file.errors.empty()) << qrterm::describe("text", file.errors);
  EXPECT_EQ(file.map.lift.axis, 2);
  EXPECT_FALSE(file.map.lift.invert);
  EXPECT_EQ(file.map.yaw.axis, 3);
  EXPECT_TRUE(file.map.roll.invert);
  EXPECT_EQ(file.map.abort_button, 1);
  EXPECT_EQ(file.map.deadband_permille, 80);
  EXPECT_EQ(file.map.stick(file.map.roll, 32767), -1000);
}

TEST(Joystick, MapFileRoundTrip) {
  JoystickMap map;
  map.pitch = {5, true};
  map.deadband_permille = 12;
  const qrterm::JoystickMapFile file = qrterm::parse_joystick_map(qrterm::format_joystick_map(map));
  ASSERT_TRUE(file.errors.empty());
  EXPECT_EQ(file.map.pitch.axis, 5);
  EXPECT_TRUE(file.map.pitch.invert);
  EXPECT_EQ(file.map.deadband_permille, 12);
}

TEST(Joystick, MapFileBadLinesAreNamedWithTheirLineNumbers) {
  const qrterm::JoystickMapFile file = qrterm::parse_joystick_map(
      "lift_axis = 1\nthrottle = 2\nroll_invert = maybe\ndeadband = 900\nyaw_axis = x\n");
  ASSERT_EQ(file.errors.size(), 5u);
  EXPECT_EQ(file.errors[0].line, 1u);
  EXPECT_NE(file.errors[0].message.find("lift_axis and pitch_axis are both axis 1"), std::string::npos)
      << file.errors[0].message;
  EXPECT_EQ(file.errors[1].line, 2u);
  EXPECT_NE(file.errors[1].message.find("unknown setting \"throttle\""), std::string::npos);
  EXPECT_EQ(file.errors[2].line, 3u);
  EXPECT_NE(file.errors[2].message.find("expected yes or no"), std::string::npos);
  EXPECT_EQ(file.errors[3].line, 4u);
  EXPECT_EQ(file.errors[4].line, 5u);
}

}  // namespace
