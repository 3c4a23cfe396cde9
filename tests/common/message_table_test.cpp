// The message table's own rules: the properties docs/protocol.md promises about type bytes and
// lengths, and that the O(1) lookups agree with the table.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include <common/frame.hpp>
#include <common/message_table.hpp>

using wire::Direction;
using wire::kMessageTable;
using wire::MessageSpec;

namespace {
int bit_count(unsigned v) {
  int n = 0;
  for (; v != 0; v &= v - 1) ++n;
  return n;
}
}  // namespace

TEST(MessageTable, TypeBytesAndNamesAreUnique) {
  std::set<uint8_t> types;
  std::set<std::string> names;
  for (const MessageSpec& spec : kMessageTable) {
    EXPECT_TRUE(types.insert(wire::type_byte(spec.type)).second) << spec.name;
    EXPECT_TRUE(names.insert(spec.name).second) << spec.name;
  }
}

TEST(MessageTable, AnyTwoTypeBytesDifferInAtLeastTwoBits) {
  for (const MessageSpec& a : kMessageTable) {
    EXPECT_EQ(bit_count(wire::type_byte(a.type)) % 2, 0) << a.name << " has odd parity";
    for (const MessageSpec& b : kMessageTable) {
      if (a.type == b.type) continue;
      EXPECT_GE(bit_count(static_cast<unsigned>(wire::type_byte(a.type) ^ wire::type_byte(b.type))), 2)
          << a.name << " vs " << b.name;
    }
  }
}

TEST(MessageTable, TopBitOfTheTypeTellsTheDirection) {
  for (const MessageSpec& spec : kMessageTable) {
    const bool from_qr = (wire::type_byte(spec.type) & 0x80u) != 0;
    EXPECT_EQ(from_qr, spec.direction == Direction::qr_to_pc) << spec.name;
  }
}

TEST(MessageTable, TypeBytesAvoidTheStartByteSmallNumbersAndText) {
  for (const MessageSpec& spec : kMessageTable) {
    const uint8_t t = wire::type_byte(spec.type);
    EXPECT_NE(t, wire::kStartByte) << spec.name;
    EXPECT_FALSE(t <= 0x0F || t >= 0xF0) << spec.name;
    // Debug text flows QR -> PC only, so only the PC's receiver hunts through text: a QR -> PC type
    // must not be a character. The QR's receiver sees no text (its PC -> QR types ran out of
    // non-printable even-parity bytes at 0x1E).
    if (spec.direction == Direction::qr_to_pc)
      EXPECT_FALSE(t >= 0x20 && t <= 0x7E) << spec.name << " is a printable character";
  }
}

TEST(MessageTable, PayloadsFitAFrameAndRequestsCarryASequenceNumber) {
  for (const MessageSpec& spec : kMessageTable) {
    EXPECT_LE(spec.payload_length, wire::kMaxPayloadBytes) << spec.name;
    if (spec.acked) {
      EXPECT_GE(spec.payload_length, 1) << spec.name << ": acked, so payload byte 0 is its sequence number";
      EXPECT_EQ(spec.direction, Direction::pc_to_qr) << spec.name << ": only the PC's requests are acked";
    }
  }
}

TEST(MessageTable, LookupAgreesWithTheTableForEveryByte) {
  for (unsigned byte = 0; byte < 256; ++byte) {
    const MessageSpec* found = wire::find_message(static_cast<uint8_t>(byte));
    const MessageSpec* expected = nullptr;
    for (const MessageSpec& spec : kMessageTable) {
      if (wire::type_byte(spec.type) == byte) expected = &spec;
    }
    EXPECT_EQ(found, expected) << byte;
  }
}

TEST(MessageTable, AckSlotsNumberTheAckedTypesOneToOne) {
  std::set<uint8_t> slots;
  for (const MessageSpec& spec : kMessageTable) {
    const uint8_t slot = wire::ack_slot(spec.type);
    if (!spec.acked) {
      EXPECT_EQ(slot, wire::kNoAckSlot) << spec.name;
      continue;
    }
    ASSERT_LT(slot, wire::kAckedTypeCount) << spec.name;
    EXPECT_TRUE(slots.insert(slot).second);
    EXPECT_EQ(wire::acked_type_at(slot), spec.type);
  }
  EXPECT_EQ(slots.size(), size_t{wire::kAckedTypeCount});
}

TEST(MessageTable, NamesComeFromTheTable) {
  EXPECT_STREQ(wire::message_name(wire::MessageType::mode_change), "mode_change");
  EXPECT_STREQ(wire::message_name(static_cast<wire::MessageType>(0x00)), "unknown");
}
