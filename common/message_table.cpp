#include <common/message_table.hpp>

namespace wire {
namespace {

// Type byte -> table row + 1 (0: no such message), and type byte -> ack slot. Built from
// kMessageTable at compile time so the table stays the only place a message is declared.
struct TypeIndex {
  uint8_t row_plus_one[256];
  uint8_t ack_slot[256];
  uint8_t acked_row[kAckedTypeCount];
};

constexpr TypeIndex make_index() {
  TypeIndex index{};
  for (uint8_t& slot_of_byte : index.ack_slot) slot_of_byte = kNoAckSlot;
  uint8_t slot = 0;
  for (size_t row = 0; row < kMessageCount; ++row) {
    const uint8_t byte = type_byte(kMessageTable[row].type);
    index.row_plus_one[byte] = static_cast<uint8_t>(row + 1);
    if (kMessageTable[row].acked) {
      index.ack_slot[byte] = slot;
      index.acked_row[slot] = static_cast<uint8_t>(row);
      ++slot;
    }
  }
  return index;
}

constexpr TypeIndex kIndex = make_index();

}  // namespace

const MessageSpec* find_message(uint8_t type) {
  const uint8_t row = kIndex.row_plus_one[type];
  return row == 0 ? nullptr : &kMessageTable[row - 1];
}

uint8_t ack_slot(MessageType type) { return kIndex.ack_slot[type_byte(type)]; }

MessageType acked_type_at(uint8_t slot) {
  return kMessageTable[kIndex.acked_row[slot < kAckedTypeCount ? slot : 0]].type;
}

const char* message_name(MessageType type) {
  const MessageSpec* spec = find_message(type_byte(type));
  return spec == nullptr ? "unknown" : spec->name;
}

}  // namespace wire
