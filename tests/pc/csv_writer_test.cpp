// CSV as spreadsheets read it, and the QR's log lines as rows under their headers.
#include <gtest/gtest.h>

#include <sstream>

#include <common/log_records.hpp>
#include <pc/core/csv_writer.hpp>
#include <pc/core/log_csv.hpp>

namespace {

using qrterm::CsvRow;
using qrterm::CsvWriter;

TEST(CsvWriter, HeaderThenRowsWithCrLf) {
  std::ostringstream out;
  CsvWriter csv(out, {"a", "b"});
  EXPECT_TRUE(csv.write(CsvRow() << int32_t{-1} << "x"));
  EXPECT_TRUE(csv.write(CsvRow() << uint16_t{65535} << ""));
  EXPECT_EQ(out.str(), "a,b\r\n-1,x\r\n65535,\r\n");
  EXPECT_EQ(csv.rows(), 2u);
}

TEST(CsvWriter, QuotesWhatMustBeQuoted) {
  EXPECT_EQ(qrterm::csv_field("plain"), "plain");
  EXPECT_EQ(qrterm::csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(qrterm::csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(qrterm::csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(qrterm::csv_field(" padded"), "\" padded\"");
}

TEST(CsvWriter, RefusesARowOfAnotherWidth) {
  std::ostringstream out;
  CsvWriter csv(out, {"a", "b", "c"});
  EXPECT_FALSE(csv.write(CsvRow() << "1"
                                  << "2"));
  EXPECT_FALSE(csv.write(CsvRow() << "1"
                                  << "2"
                                  << "3"
                                  << "4"));
  EXPECT_EQ(out.str(), "a,b,c\r\n");
  EXPECT_EQ(csv.rows(), 0u);
}

// The lines of golden frames G19-G22 (docs/protocol.md section 11).
TEST(CsvWriter, SensorLogLineUnderItsHeader) {
  wire::SensorLogRecord r;
  r.line = 1000;
  r.time_us = 123456789;
  const int16_t gyro[] = {-12, 7, 300}, accel[] = {250, -180, 16384}, gyro_f[] = {-10, 5, 298},
                accel_f[] = {248, -177, 16380};
  for (int i = 0; i < 3; ++i) {
    r.gyro[i] = gyro[i];
    r.accel[i] = accel[i];
    r.gyro_filtered[i] = gyro_f[i];
    r.accel_filtered[i] = accel_f[i];
  }
  r.battery_mv = 11850;
  std::ostringstream out;
  CsvWriter csv(out, qrterm::log_header(r));
  ASSERT_TRUE(csv.write(qrterm::log_row(r)));
  EXPECT_EQ(out.str(),
            "line,time_us,gyro_x_counts,gyro_y_counts,gyro_z_counts,accel_x_counts,accel_y_counts,accel_z_counts,"
            "gyro_filtered_x_counts,gyro_filtered_y_counts,gyro_filtered_z_counts,"
            "accel_filtered_x_counts,accel_filtered_y_counts,accel_filtered_z_counts,battery_mv\r\n"
            "1000,123456789,-12,7,300,250,-180,16384,-10,5,298,248,-177,16380,11850\r\n");
}

TEST(CsvWriter, TelemetryLogLineUnderItsHeader) {
  wire::TelemetryLogRecord r;
  r.line = 17;
  r.time_us = 5000000;
  r.mode = wire::Mode::full_control;
  r.flags = 3;
  r.lift = 450;
  r.roll = -873;
  r.yaw_rate = 500;
  r.phi = -850;
  r.theta = 12;
  r.psi = 31416;
  r.p = -20;
  r.q = 3;
  r.r = 495;
  const uint16_t engines[] = {400, 410, 395, 405};
  for (int i = 0; i < 4; ++i) r.engine[i] = engines[i];
  r.loop_time_us = 612;
  r.battery_mv = 11850;
  r.cpu_load = 623;
  r.deadline_misses = 3;
  std::ostringstream out;
  CsvWriter csv(out, qrterm::log_header(r));
  ASSERT_TRUE(csv.write(qrterm::log_row(r)));
  EXPECT_EQ(out.str().substr(0, out.str().find("\r\n")),
            "line,time_us,mode,flags,lift_sp_0to1000,roll_sp_1e-4rad,pitch_sp_1e-4rad,yaw_rate_sp_1e-3rad_s,"
            "phi_1e-4rad,theta_1e-4rad,psi_1e-4rad,p_1e-3rad_s,q_1e-3rad_s,r_1e-3rad_s,"
            "engine_front_0to1000,engine_right_0to1000,engine_back_0to1000,engine_left_0to1000,"
            "loop_time_us,battery_mv,cpu_load_permille,deadline_misses");
  EXPECT_EQ(out.str().substr(out.str().find("\r\n") + 2),
            "17,5000000,5,3,450,-873,0,500,-850,12,31416,-20,3,495,400,410,395,405,612,11850,623,3\r\n");
}

}  // namespace
