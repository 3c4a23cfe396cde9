// The vehicle put together wrong (sim/wiring.hpp): the rows read and refused as the vehicle file
// and the scenarios write them, the IMU reading through its mounting, outputs driving the rotors
// they are soldered to, and a motor turning the wrong way.
#include <gtest/gtest.h>

#include <qr/core/chain/imu_mounting.hpp>
#include <sim/quadrotor.hpp>
#include <sim/rotor.hpp>
#include <sim/vehicle.hpp>
#include <sim/wiring.hpp>

namespace sim {
namespace {

TEST(Wiring, RowsReadAndMistakesAreNamed) {
  Wiring w;
  std::string error;
  EXPECT_TRUE(parse_wiring_row("motor_outputs", "1 0 2 3", w, error)) << error;
  EXPECT_TRUE(parse_wiring_row("motor_reversed", "0 0 1 0", w, error)) << error;
  EXPECT_TRUE(parse_wiring_row("imu_mount_yaw_deg", "270", w, error)) << error;
  EXPECT_TRUE(parse_wiring_row("imu_upside_down", "1", w, error)) << error;
  EXPECT_TRUE(parse_wiring_row("gyro_signs", "1 -1 1", w, error)) << error;
  EXPECT_EQ(wiring_text(w),
            "motor_outputs = 1 0 2 3\nmotor_reversed = 0 0 1 0\nimu_mount_yaw_deg = 270\nimu_upside_down = 1\n"
            "gyro_signs = 1 -1 1\n");
  const struct {
    const char* name;
    const char* values;
    const char* said;
  } bad[] = {
      {"motor_outputs", "0 0 2 3", "each once"},    {"motor_outputs", "0 1 2", "needs 4 numbers"},
      {"motor_reversed", "0 2 0 0", "0 or 1"},      {"imu_mount_yaw_deg", "45", "0, 90, 180 or 270"},
      {"gyro_signs", "1 0 1", "1 or -1"},           {"accel_signs", "1 x 1", "not a whole number"},
      {"imu_upside_down", "1 1", "needs 1 number"},
  };
  for (const auto& b : bad) {
    Wiring untouched;
    EXPECT_FALSE(parse_wiring_row(b.name, b.values, untouched, error)) << b.name << " " << b.values;
    EXPECT_NE(error.find(b.said), std::string::npos) << error;
    EXPECT_NE(error.find(b.name), std::string::npos) << error;
  }
}

TEST(Wiring, AVehicleFileCarriesItAndNamesTheLineOfAMistake) {
  VehicleParams v;
  std::string error;
  const std::string text = default_vehicle_text();
  ASSERT_TRUE(parse_vehicle(text + "\nmotor_outputs = 0 3 2 1\n", v, error)) << error;
  EXPECT_EQ(v.wiring.rotor_of_output, (std::array<int, 4>{0, 3, 2, 1}));
  ASSERT_TRUE(parse_vehicle(text, v, error)) << error;
  EXPECT_EQ(v.wiring, Wiring{}) << "absent rows: the right wiring";
  EXPECT_FALSE(parse_vehicle(text + "\nimu_mount_yaw_deg = 30\n", v, error));
  EXPECT_NE(error.find("line "), std::string::npos) << error;
  EXPECT_NE(error.find("imu_mount_yaw_deg"), std::string::npos) << error;
}

// Body axes x forward, y right, z down. A board turned 90 degrees clockwise has its X arrow on
// body y: a roll rate (about x) reads on its -y, a pitch rate on its x.
TEST(Wiring, TheImuReadsThroughItsMounting) {
  const Vec3 roll{1, 0, 0}, pitch{0, 1, 0}, gravity{0, 0, -9.8};
  Wiring w;
  const auto same = [](const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
  EXPECT_TRUE(same(imu_gyro_axes(w, roll), roll));
  w.imu_yaw_deg = 90;
  EXPECT_TRUE(same(imu_gyro_axes(w, roll), Vec3{0, -1, 0}));
  EXPECT_TRUE(same(imu_gyro_axes(w, pitch), Vec3{1, 0, 0}));
  EXPECT_TRUE(same(imu_accel_axes(w, gravity), gravity)) << "turned about z, gravity stays on z";
  w = Wiring{};
  w.imu_upside_down = 1;
  EXPECT_TRUE(same(imu_accel_axes(w, gravity), Vec3{0, 0, 9.8}));
  EXPECT_TRUE(same(imu_gyro_axes(w, pitch), Vec3{0, -1, 0}));
  w = Wiring{};
  w.gyro_signs = {1, -1, 1};
  EXPECT_TRUE(same(imu_gyro_axes(w, pitch), Vec3{0, -1, 0}));
  EXPECT_TRUE(same(imu_accel_axes(w, gravity), gravity)) << "the gyro's sign is not the accelerometer's";
}

// The rotors' speeds after a second at one engine command, as the plant integrates them.
std::array<double, 4> speeds_after(const VehicleParams& v, const std::array<uint16_t, 4>& engines) {
  Quadrotor plant(v);
  plant.set_engines(engines);
  for (int i = 0; i < 1000; ++i) plant.step(0.001);
  return plant.state().rotor_speed;
}

TEST(Wiring, EachOutputDrivesTheRotorItIsSolderedTo) {
  VehicleParams v = default_vehicle();
  v.wiring.rotor_of_output = {1, 0, 2, 3};
  const auto w = speeds_after(v, {300, 0, 0, 0});  // output 0 (front, rightly) drives rotor 1 (right)
  EXPECT_GT(w[1], 100);
  EXPECT_EQ(w[0], 0);
}

// A motor turning the wrong way pushes down at half the thrust and its torque turns the other way.
TEST(Wiring, AReversedMotorPushesDownAndTurnsTheOtherWay) {
  VehicleParams v = default_vehicle();
  const RotorGeometry right = rotor_geometry(v)[3];
  v.wiring.reversed = {0, 0, 0, 1};
  const RotorGeometry reversed = rotor_geometry(v)[3];
  const double speed = v.hover_speed();
  const Wrench r = rotor_wrench(v, right, speed, 0, {}, {});
  const Wrench x = rotor_wrench(v, reversed, speed, 0, {}, {});
  EXPECT_LT(r.force.z, 0) << "rightly: thrust up (body z points down)";
  EXPECT_DOUBLE_EQ(x.force.z, -kReversedThrustShare * r.force.z);
  EXPECT_DOUBLE_EQ(x.torque.z, -r.torque.z);
  EXPECT_GT(r.torque.x, 0) << "the left rotor lifts the left side: a roll right";
  EXPECT_LT(x.torque.x, 0) << "reversed, it pushes the left side down";
  EXPECT_EQ(rotor_geometry(v)[0].lift, 1) << "the others untouched";
}

// An ESC set to spin direction 2 (a DShot command, qr/boards/sim/sim_esc.hpp) turns the rotor its
// output drives the other way: a wrongly wired motor right again, a right one wrong.
TEST(Wiring, AnEscsDirectionTurnsTheRotorItsOutputDrives) {
  VehicleParams v = default_vehicle();
  v.wiring.rotor_of_output = {3, 1, 2, 0};  // output 0 drives the left rotor
  v.wiring.reversed = {0, 0, 0, 1};         // which turns the wrong way
  Quadrotor plant(v);
  ASSERT_EQ(plant.rotors()[3].spin, +1) << "the left rotor wired clockwise";
  plant.set_output_reversed(0, true);
  EXPECT_EQ(plant.rotors()[3].spin, -1) << "counter-clockwise, as the left rotor must";
  EXPECT_EQ(plant.rotors()[3].lift, 1) << "and it lifts";
  EXPECT_EQ(plant.rotors()[0].spin, +1) << "the front rotor untouched";
  plant.set_output_reversed(0, false);
  EXPECT_EQ(plant.rotors()[3].spin, +1);
  EXPECT_EQ(plant.rotors()[3].lift, -kReversedThrustShare) << "back as wired";
}

// The firmware's imu_orientation = k + 4 u (qr/core/chain/imu_mounting.hpp) undoes the mounting
// imu_mount_yaw_deg = 90 k, imu_upside_down = u: every body vector comes back as it was.
TEST(Wiring, EachImuOrientationUndoesItsMounting) {
  const Vec3 probes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {3, -5, 7}};
  for (int k = 0; k < 4; ++k) {
    for (int u = 0; u < 2; ++u) {
      Wiring w;
      w.imu_yaw_deg = 90 * k;
      w.imu_upside_down = u;
      for (const Vec3& v : probes) {
        const Vec3 board = imu_gyro_axes(w, v);
        qr::SensorSample s;
        s.gyro[0] = static_cast<int16_t>(board.x);
        s.gyro[1] = static_cast<int16_t>(board.y);
        s.gyro[2] = static_cast<int16_t>(board.z);
        s.accel[0] = s.gyro[0];
        s.accel[1] = s.gyro[1];
        s.accel[2] = s.gyro[2];
        const qr::SensorSample body = qr::chain::mounted(qr::chain::imu_mounting(k + 4 * u), s);
        for (int i = 0; i < 3; ++i) {
          const double want = i == 0 ? v.x : i == 1 ? v.y : v.z;
          EXPECT_EQ(body.gyro[i], want) << "yaw " << 90 * k << " upside down " << u << " axis " << i;
          EXPECT_EQ(body.accel[i], want);
        }
      }
    }
  }
}

}  // namespace
}  // namespace sim
