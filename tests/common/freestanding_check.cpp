// Compiled with the freestanding flags (no exceptions, no RTTI, no thread-safe statics) and only
// the headers common/ allows: every template of the wire instantiated the way the QR uses it.
#include <stddef.h>
#include <stdint.h>

#include <common/drivers/mpu6050.hpp>
#include <common/drivers/ms5611.hpp>
#include <common/frame_parser.hpp>
#include <common/log_downloader.hpp>
#include <common/messages.hpp>
#include <common/parameter_table.hpp>
#include <common/request_dedup.hpp>
#include <common/resend_queue.hpp>

namespace {

// The console's download logic is common/ too: it must build freestanding (8 KiB of line bits,
// so not on the stack).
wire::LogDownloader<wire::SensorLogRecord, 1024> download;

struct EveryMessage {
  uint32_t handled = 0;
  template <wire::Message Msg>
  void operator()(const Msg& message) {
    handled += wire::encode(message).size;
  }
};

template <class Msg>
uint32_t decodes_as(const wire::Frame& frame) {
  Msg message{};
  return wire::decode(frame, message) ? 1u : 0u;
}

template <class... Msgs>
uint32_t decoders_accepting(const wire::Frame& frame, wire::MessageList<Msgs...>) {
  return (decodes_as<Msgs>(frame) + ... + 0u);
}

// The MPU-6050 driver's step over a bus of nothing but the concept (a template in the header).
struct SilentBus {
  bool begin(const drivers::I2cTransfer&) { return true; }
  drivers::I2cResult poll(drivers::I2cReply&) { return drivers::I2cResult::ok; }
};

drivers::Mpu6050 mpu6050_driver;

}  // namespace

uint32_t mpu6050_freestanding_check(uint32_t now_us) {
  SilentBus bus;
  mpu6050_driver.step(bus, now_us);
  return mpu6050_driver.bus_bits_this_tick() + mpu6050_driver.total_faults();
}

uint32_t wire_freestanding_check(const uint8_t* bytes, size_t length, uint32_t now_ms) {
  wire::FrameParser parser(wire::Listen::both);
  wire::ResendQueue queue;
  wire::RequestDedup dedup;
  wire::LogLineAssembler<wire::SensorLogRecord> sensor;
  wire::LogLineAssembler<wire::TelemetryLogRecord> telemetry;
  download.begin(100);
  EveryMessage handler;
  uint32_t total = 0;
  for (size_t i = 0; i < length; ++i) {
    parser.push(bytes[i], [&](const wire::Frame& frame) {
      wire::dispatch(frame, handler);
      total += decoders_accepting(frame, wire::AllMessages{});
      const wire::Admission a = dedup.admit(frame, now_ms);
      if (a.request && !a.duplicate) dedup.record(frame, wire::NackReason::none, now_ms);
      wire::SensorLogPart sp;
      wire::SensorLogRecord sr;
      if (wire::decode(frame, sp)) sensor.add(sp, sr);
      wire::TelemetryLogPart tp;
      wire::TelemetryLogRecord tr;
      if (wire::decode(frame, tp)) telemetry.add(tp, tr);
      if (wire::decode(frame, sp)) download.on_part(sp, now_ms, [&](const wire::SensorLogRecord&) { ++total; });
    });
  }
  wire::LogResend resend;
  if (download.next_resend(now_ms, resend)) total += queue.submit(resend, now_ms).size;
  const wire::FrameBytes sent[] = {queue.submit(wire::ModeChange{}, now_ms), queue.submit(wire::ParamSet{}, now_ms),
                                   queue.submit(wire::ParamGet{}, now_ms),   queue.submit(wire::LogStart{}, now_ms),
                                   queue.submit(wire::LogStop{}, now_ms),    queue.submit(wire::LogDownload{}, now_ms),
                                   queue.submit(wire::Exit{}, now_ms)};
  for (const wire::FrameBytes& frame : sent) total += frame.size;
  wire::ResendEvent event;
  while (queue.poll(now_ms + wire::kResendIntervalMs, event)) total += event.frame.size;
  return total + handler.handled;
}

// The MS5611 driver's step (a template in the header) over a bus where nobody answers, and the
// compensation.
namespace {

struct NoChipBus {
  bool begin(const drivers::I2cTransfer&) { return true; }
  drivers::I2cResult poll(drivers::I2cReply&) { return drivers::I2cResult::address_nack; }
};

drivers::Ms5611 ms5611_driver;

}  // namespace

uint32_t ms5611_freestanding_check(uint32_t now_us) {
  NoChipBus bus;
  ms5611_driver.step(bus, now_us);
  drivers::Ms5611Reading reading;
  const bool fresh = ms5611_driver.take(reading);
  const drivers::Ms5611Reading r = drivers::compensate(ms5611_driver.prom(), now_us, now_us);
  return ms5611_driver.total_faults() + (fresh ? 1u : 0u) + static_cast<uint32_t>(r.pressure_pa);
}
