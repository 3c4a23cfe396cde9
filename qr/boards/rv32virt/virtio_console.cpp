// The split virtqueues of the virtio 1.x specification (section 2.7), over the virtio-mmio
// register block (section 4.2.2), for a console device (section 5.3) without its features.
#include <qr/boards/rv32virt/virtio_console.hpp>

#include <qr/boards/rv32virt/virt_map.hpp>

namespace rv32virt {
namespace {

using map::reg;

// virtio-mmio registers (offsets in the slot).
constexpr uintptr_t kMagic = 0x000, kVersion = 0x004, kDeviceId = 0x008, kDriverFeatures = 0x020,
                    kDriverFeaturesSel = 0x024, kQueueSel = 0x030, kQueueNum = 0x038, kQueueReady = 0x044,
                    kQueueNotify = 0x050, kStatus = 0x070, kQueueDescLow = 0x080, kQueueDescHigh = 0x084,
                    kQueueDriverLow = 0x090, kQueueDriverHigh = 0x094, kQueueDeviceLow = 0x0a0,
                    kQueueDeviceHigh = 0x0a4;
constexpr uint32_t kMagicValue = 0x74726976;  // "virt"
constexpr uint32_t kConsoleDevice = 3;
constexpr uint32_t kStatusAcknowledge = 1, kStatusDriver = 2, kStatusDriverOk = 4, kStatusFeaturesOk = 8;
constexpr uint32_t kFeatureVersion1 = 1;  // bit 32: the modern interface (word 1, bit 0)
constexpr uint16_t kDescWrite = 2;        // the device writes this buffer

constexpr uint16_t kQueueSize = 4;  // buffers per queue: a frame or two is all that is ever in flight
constexpr uint32_t kReceiveQueue = 0, kTransmitQueue = 1;

struct Descriptor {
  uint64_t address;
  uint32_t length;
  uint16_t flags;
  uint16_t next;
};
struct Available {
  uint16_t flags;
  uint16_t index;
  uint16_t ring[kQueueSize];
  uint16_t used_event;
};
struct UsedEntry {
  uint32_t id;
  uint32_t length;
};
struct Used {
  uint16_t flags;
  uint16_t index;
  UsedEntry ring[kQueueSize];
  uint16_t avail_event;
};
struct Queue {
  alignas(16) Descriptor descriptors[kQueueSize];
  alignas(4) Available available;
  alignas(4) Used used;
  uint8_t buffers[kQueueSize][VirtioConsole::kBufferBytes];
};

Queue g_receive;
Queue g_transmit;

void fence() { asm volatile("fence rw, rw" ::: "memory"); }

uint32_t address_of(const void* p) { return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(p)); }

volatile uint32_t& slot_reg(uintptr_t base, uintptr_t offset) { return reg<uint32_t>(base + offset); }

uint16_t used_index(const Queue& q) { return *reinterpret_cast<const volatile uint16_t*>(&q.used.index); }

void set_up_queue(uintptr_t base, uint32_t index, Queue& q) {
  slot_reg(base, kQueueSel) = index;
  slot_reg(base, kQueueNum) = kQueueSize;
  slot_reg(base, kQueueDescLow) = address_of(q.descriptors);
  slot_reg(base, kQueueDescHigh) = 0;
  slot_reg(base, kQueueDriverLow) = address_of(&q.available);
  slot_reg(base, kQueueDriverHigh) = 0;
  slot_reg(base, kQueueDeviceLow) = address_of(&q.used);
  slot_reg(base, kQueueDeviceHigh) = 0;
  slot_reg(base, kQueueReady) = 1;
}

}  // namespace

bool VirtioConsole::start() {
  for (uint32_t slot = 0; slot < map::kVirtioSlots; ++slot) {
    const uintptr_t base = map::kVirtio + slot * map::kVirtioSlotBytes;
    if (slot_reg(base, kMagic) != kMagicValue || slot_reg(base, kVersion) != 2 ||
        slot_reg(base, kDeviceId) != kConsoleDevice) {
      continue;
    }
    slot_reg(base, kStatus) = kStatusAcknowledge;
    slot_reg(base, kStatus) = kStatusAcknowledge | kStatusDriver;
    // Version 2 devices offer VERSION_1, the one feature taken: nothing to check first.
    slot_reg(base, kDriverFeaturesSel) = 0;
    slot_reg(base, kDriverFeatures) = 0;  // no multiport, no console size, no emergency write
    slot_reg(base, kDriverFeaturesSel) = 1;
    slot_reg(base, kDriverFeatures) = kFeatureVersion1;
    // (The device takes no feature but VERSION_1 and offers queues of 128: nothing to check.)
    slot_reg(base, kStatus) = kStatusAcknowledge | kStatusDriver | kStatusFeaturesOk;

    // Every receive buffer goes to the device at once; transmit buffers when there is something.
    for (uint16_t i = 0; i < kQueueSize; ++i) {
      g_receive.descriptors[i] = {address_of(g_receive.buffers[i]), kBufferBytes, kDescWrite, 0};
      g_receive.available.ring[i] = i;
      g_transmit.descriptors[i] = {address_of(g_transmit.buffers[i]), 0, 0, 0};
    }
    g_receive.available.index = kQueueSize;
    set_up_queue(base, kReceiveQueue, g_receive);
    set_up_queue(base, kTransmitQueue, g_transmit);
    fence();
    slot_reg(base, kStatus) = kStatusAcknowledge | kStatusDriver | kStatusFeaturesOk | kStatusDriverOk;
    slot_reg(base, kQueueNotify) = kReceiveQueue;
    base_ = base;
    return true;
  }
  return false;
}

bool VirtioConsole::next_received(const uint8_t*& bytes, size_t& length) {
  fence();
  if (used_index(g_receive) == rx_seen_) return false;
  const UsedEntry& e = g_receive.used.ring[rx_seen_ % kQueueSize];
  const uint32_t id = e.id % kQueueSize;
  bytes = g_receive.buffers[id];
  length = e.length <= kBufferBytes ? e.length : kBufferBytes;
  return true;
}

void VirtioConsole::recycle_received() {
  const uint32_t id = g_receive.used.ring[rx_seen_ % kQueueSize].id % kQueueSize;
  ++rx_seen_;
  g_receive.available.ring[g_receive.available.index % kQueueSize] = static_cast<uint16_t>(id);
  fence();
  g_receive.available.index = static_cast<uint16_t>(g_receive.available.index + 1);
  fence();
  slot_reg(base_, kQueueNotify) = kReceiveQueue;  // the device may have been waiting for room
}

void VirtioConsole::send(const uint8_t* bytes, size_t length) {
  if (length > kBufferBytes) length = kBufferBytes;
  // A buffer is free again once the device has put it in the used ring.
  for (;;) {
    fence();
    tx_seen_ = used_index(g_transmit);
    if (static_cast<uint16_t>(tx_posted_ - tx_seen_) < kQueueSize) break;
  }
  const uint16_t id = static_cast<uint16_t>(tx_posted_ % kQueueSize);
  for (size_t i = 0; i < length; ++i) g_transmit.buffers[id][i] = bytes[i];
  g_transmit.descriptors[id].length = static_cast<uint32_t>(length);
  g_transmit.available.ring[g_transmit.available.index % kQueueSize] = id;
  fence();
  g_transmit.available.index = static_cast<uint16_t>(g_transmit.available.index + 1);
  ++tx_posted_;
  fence();
  slot_reg(base_, kQueueNotify) = kTransmitQueue;
}

}  // namespace rv32virt
