// The serve mode side channel's command parser and truth line (qr/boards/sim/truth_channel.hpp).
#include <gtest/gtest.h>

#include <qr/boards/sim/truth_channel.hpp>

namespace {

TEST(TruthChannel, ParsesAPush) {
  qrsim::TruthPush push;
  std::string error;
  ASSERT_TRUE(qrsim::parse_truth_command("push 0.3 -0.1 0 0.1", push, error)) << error;
  EXPECT_DOUBLE_EQ(push.torque.x, 0.3);
  EXPECT_DOUBLE_EQ(push.torque.y, -0.1);
  EXPECT_DOUBLE_EQ(push.torque.z, 0.0);
  EXPECT_DOUBLE_EQ(push.seconds, 0.1);
  ASSERT_TRUE(qrsim::parse_truth_command("  push\t1 2 3 0.5\r", push, error)) << error;
  EXPECT_DOUBLE_EQ(push.torque.z, 3.0);
}

TEST(TruthChannel, RefusesBadLines) {
  qrsim::TruthPush push;
  std::string error;
  EXPECT_FALSE(qrsim::parse_truth_command("", push, error));
  EXPECT_EQ(error, "empty command");
  EXPECT_FALSE(qrsim::parse_truth_command("shove 1 2 3 4", push, error));
  EXPECT_EQ(error.rfind("unknown command 'shove'", 0), 0u) << error;
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 2 3", push, error));
  EXPECT_EQ(error, "push needs TX TY TZ SECONDS");
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 2 3 4 5", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 x 3 0.1", push, error));
  EXPECT_EQ(error, "bad number 'x'");
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 nan 3 0.1", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 11 0 0 0.1", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 0 0 0", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 0 0 -1", push, error));
  EXPECT_FALSE(qrsim::parse_truth_command("push 1 0 0 11", push, error));
}

TEST(TruthChannel, TruthLineFormat) {
  sim::PlantState s;
  s.position = {0.1, -0.02, -1.5};
  s.velocity = {0, 0, -0.25};
  EXPECT_EQ(qrsim::truth_line(12.34, s),
            "truth t=12.340 roll=0.00 pitch=0.00 yaw=0.00 height=1.500 north=0.100 east=-0.020 climb=0.250\n");
}

}  // namespace
