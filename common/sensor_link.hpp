// The sensor link: the serial stream between the devboard and the simulator that carries what the
// IN4073's FPGA and interface board exchanged (sensor samples in, engine values out), so that the
// cross-compiled firmware flies in the simulated world (docs/devboard.md, "The sensor link").
//
// Lock-step: the simulator sends the samples of control period k (a `SensorFrame`); its arrival
// is the board's kick, its time stamp the board's clock; the board answers with an `EngineFrame`
// for period k, and only then does the simulator advance the plant by one period. The frames also
// count the ground line's bytes each way, so the bytes the console sent before period k are in
// the QR's receive ring before its tick k runs, and the simulator knows which bytes the QR sent
// in which tick: a run is deterministic whatever the host's load.
//
// Frame: 'S' (0x53), type, the type's fixed-length payload, CRC-8 (crc8.hpp) over type and
// payload. Little-endian, field by field (payload_codec.hpp). The stream underneath is lossless
// (virtio), so the check byte is there to find the next frame after a bad byte, not to correct a
// noisy line: frames are longer than the 9 payload bytes for which the wire's CRC-8 promises
// Hamming distance 4.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/drivers/i2c.hpp>
#include <common/payload_codec.hpp>

namespace simlink {

inline constexpr uint8_t kStart = 'S';

enum class LinkType : uint8_t {
  sensors = 0x01,    // simulator -> QR: one control period's samples (the kick)
  i2c_done = 0x02,   // simulator -> QR: a transfer on the sensors' I2C bus ended (before a kick)
  engines = 0x81,    // QR -> simulator: the answer to a sensors frame
  i2c_begin = 0x82,  // QR -> simulator: a driver began a transfer on the sensors' I2C bus
};

// Who listens: the QR reads the simulator's types (below 0x80), the simulator the QR's.
enum class LinkEnd : uint8_t { qr, simulator };

struct SensorFrame {
  static constexpr LinkType kType = LinkType::sensors;
  uint32_t kick = 0;     // the control period's number (the simulator's time / period)
  uint32_t time_us = 0;  // the simulator's time of the sample, µs (wraps as the board's clock)
  int16_t gyro[3] = {0, 0, 0};
  int16_t accel[3] = {0, 0, 0};
  uint16_t battery_mv = 0;
  int32_t pressure_pa = 0;
  uint32_t ground_bytes = 0;  // bytes the simulator has put on the QR's ground line so far (wraps)
  // 1: the sensors are chips on an I2C bus the link carries (the frames below), read by the
  // firmware's own drivers; gyro, accel and pressure above are then 0 and unused. 0: the samples.
  uint8_t sensors_on_i2c = 0;

  template <class Self, class V>
  static constexpr void fields(Self& s, V& v) {
    v(s.kick), v(s.time_us), v(s.gyro), v(s.accel), v(s.battery_mv), v(s.pressure_pa), v(s.ground_bytes);
    v(s.sensors_on_i2c);
  }
  constexpr bool valid() const { return sensors_on_i2c <= 1; }
};

// The sensors' I2C bus carried over the link (docs/devboard.md, "The sensor link"): the board's
// bus sends each transfer a driver begins (common/drivers/i2c.hpp, a channel per driver) as it is
// begun; the simulator plays it on its chip models at the tick's time, as the host build's bus
// does, and sends its end before the first kick at which the wire has finished it. In lock-step
// the tick's transfers reach the chips at the same simulated instants as on the host, so the
// drivers read the same bytes.
struct I2cBeginFrame {
  static constexpr LinkType kType = LinkType::i2c_begin;
  uint8_t channel = 0;
  uint8_t address = 0;
  uint8_t write[drivers::kI2cMaxWrite] = {};
  uint8_t write_count = 0;
  uint8_t read_count = 0;

  template <class Self, class V>
  static constexpr void fields(Self& s, V& v) {
    v(s.channel), v(s.address), v(s.write), v(s.write_count), v(s.read_count);
  }
  constexpr bool valid() const { return write_count <= drivers::kI2cMaxWrite && read_count <= drivers::kI2cMaxRead; }
};

struct I2cDoneFrame {
  static constexpr LinkType kType = LinkType::i2c_done;
  uint8_t channel = 0;
  uint8_t result = 0;  // drivers::I2cResult
  uint8_t count = 0;   // bytes read
  uint8_t data[drivers::kI2cMaxRead] = {};

  template <class Self, class V>
  static constexpr void fields(Self& s, V& v) {
    v(s.channel), v(s.result), v(s.count), v(s.data);
  }
  constexpr bool valid() const {
    return result <= static_cast<uint8_t>(drivers::I2cResult::bus_stuck) && count <= drivers::kI2cMaxRead;
  }
};

// What the host build's scorer reads from the firmware's memory, the devboard sends: the engines,
// and the mode, estimate and set-points the figures are judged against (truth minus set-point).
// Only what the figures need (the yaw estimate and the estimated rates, which only a trace shows,
// stay out), in arrays: the devboard's 64 KiB image has little room for the code of each field.
struct EngineFrame {
  static constexpr LinkType kType = LinkType::engines;
  enum Angle : uint8_t { roll_estimate, pitch_estimate, roll_setpoint, pitch_setpoint, kAngles };
  enum Stat : uint8_t { count, max, overruns, sum_low, sum_high, kStats };

  uint32_t kick = 0;  // the sensors frame this answers
  uint16_t engines[4] = {0, 0, 0, 0};
  uint8_t mode = 0;
  uint8_t flags = 0;          // the QR's telemetry flags (wire::kFlag*: calibrated, flying, ...)
  uint32_t ground_bytes = 0;  // bytes the QR has written to its ground line so far (wraps)
  uint32_t deadline_misses = 0;
  int16_t angles_e4[kAngles] = {};   // 1e-4 rad, in Angle order
  int16_t yaw_rate_setpoint_e3 = 0;  // 1e-3 rad/s
  // One row of the scheduler's statistics (qr/core/cycle_stats.hpp, instructions; Stat order), a
  // different row each tick: rows 0 .. task count - 1 are the task table's, row `task count` the
  // whole tick. Round the rows go, so the simulator's copy is never more than a row count of
  // ticks old, and the board needs no request and no second kind of frame to report them.
  uint8_t stats_row = 0;
  uint32_t stats[kStats] = {};
  // With the sensors on the link's I2C bus: the drivers' verdicts (bit 0 the IMU streams, bit 1
  // the barometer measures) and counts since power-up, in qr::SensorCounts order (imu samples,
  // faults, lost; barometer readings, faults, ADC reads of 0). All 0 otherwise.
  uint8_t sensors_healthy = 0;
  uint32_t sensor_counts[6] = {};

  template <class Self, class V>
  static constexpr void fields(Self& s, V& v) {
    v(s.kick), v(s.engines), v(s.mode), v(s.flags), v(s.ground_bytes), v(s.deadline_misses), v(s.angles_e4);
    v(s.yaw_rate_setpoint_e3), v(s.stats_row), v(s.stats), v(s.sensors_healthy), v(s.sensor_counts);
  }
  constexpr bool valid() const { return true; }
};

// Payload bytes of a type; 0 for a type this end does not listen to (nothing has an empty payload).
template <class Msg>
constexpr size_t payload_if(uint8_t type) {
  return type == static_cast<uint8_t>(Msg::kType) ? wire::wire_size<Msg>() : 0;
}
constexpr size_t payload_length(LinkEnd listener, uint8_t type) {
  if (listener == LinkEnd::qr) return payload_if<SensorFrame>(type) + payload_if<I2cDoneFrame>(type);
  return payload_if<EngineFrame>(type) + payload_if<I2cBeginFrame>(type);
}

inline constexpr size_t kMaxLinkPayload = 80;
inline constexpr size_t kLinkOverhead = 3;  // start, type, check
inline constexpr size_t kMaxLinkFrame = kMaxLinkPayload + kLinkOverhead;
static_assert(wire::wire_size<EngineFrame>() <= kMaxLinkPayload && wire::wire_size<SensorFrame>() <= kMaxLinkPayload);
static_assert(wire::wire_size<I2cBeginFrame>() <= kMaxLinkPayload &&
              wire::wire_size<I2cDoneFrame>() <= kMaxLinkPayload);

// CRC-8 of the wire (crc8.hpp) over a frame's type and payload.
uint8_t check(const uint8_t* type_and_payload, size_t length);

struct LinkFrameBytes {
  uint8_t bytes[kMaxLinkFrame] = {};
  uint8_t size = 0;
};

// Field by field, little-endian, as payload_codec.hpp's writer and reader, but each field a call
// into sensor_link.cpp rather than inlined: the link is not flight code, and on the devboard its
// frames must fit in the 64 KiB image beside the flight's.
class LinkWriter {
 public:
  explicit LinkWriter(uint8_t* out) : out_(out) {}
  void operator()(uint8_t v);
  void operator()(uint16_t v);
  void operator()(int16_t v) { (*this)(static_cast<uint16_t>(v)); }
  void operator()(uint32_t v);
  void operator()(int32_t v) { (*this)(static_cast<uint32_t>(v)); }
  template <class T, size_t N>
  void operator()(const T (&array)[N]) {
    for (const T& element : array) (*this)(element);
  }
  size_t size() const { return size_; }

 private:
  uint8_t* out_;
  size_t size_ = 0;
};

class LinkReader {
 public:
  explicit LinkReader(const uint8_t* in) : in_(in) {}
  void operator()(uint8_t& v);
  void operator()(uint16_t& v);
  void operator()(uint32_t& v);
  void operator()(int16_t& v) {
    uint16_t raw = 0;
    (*this)(raw);
    v = static_cast<int16_t>(raw);
  }
  void operator()(int32_t& v) {
    uint32_t raw = 0;
    (*this)(raw);
    v = static_cast<int32_t>(raw);
  }
  template <class T, size_t N>
  void operator()(T (&array)[N]) {
    for (T& element : array) (*this)(element);
  }

 private:
  const uint8_t* in_;
};

// Puts start, type and check around a payload of `length` bytes written at bytes + 2.
void frame_around(LinkFrameBytes& frame, LinkType type, size_t length);

// One frame of a link message, ready to send.
template <class Msg>
LinkFrameBytes encode(const Msg& message) {
  LinkFrameBytes out;
  LinkWriter writer(out.bytes + 2);
  Msg::fields(message, writer);
  frame_around(out, Msg::kType, writer.size());
  return out;
}

// A complete frame as the parser hands it over: its type and payload.
struct LinkFrame {
  uint8_t type = 0;
  uint8_t length = 0;
  const uint8_t* payload = nullptr;

  // The parser has checked the length against the type, so the fields are all there.
  template <class Msg>
  bool decode(Msg& out) const {
    if (type != static_cast<uint8_t>(Msg::kType)) return false;
    Msg message;
    LinkReader reader(payload);
    Msg::fields(message, reader);
    if (!message.valid()) return false;
    out = message;
    return true;
  }
};

// Byte-at-a-time, never blocks, keeps at most one frame's bytes; after a bad check it looks for
// the next start from the byte after the one it took for a start.
class LinkParser {
 public:
  explicit constexpr LinkParser(LinkEnd listener) : listener_(listener) {}

  template <class OnFrame>
  void push(uint8_t byte, OnFrame&& on_frame) {
    buffer_[length_++] = byte;
    LinkFrame frame;
    while (advance(frame)) on_frame(static_cast<const LinkFrame&>(frame));
  }

  uint32_t frames() const { return frames_; }
  uint32_t bytes_skipped() const { return skipped_; }

 private:
  bool advance(LinkFrame& frame);
  void drop(size_t count);

  LinkEnd listener_;
  uint8_t buffer_[kMaxLinkFrame] = {};
  size_t length_ = 0;
  uint8_t payload_[kMaxLinkPayload] = {};  // the frame handed out last
  uint32_t frames_ = 0;
  uint32_t skipped_ = 0;
};

}  // namespace simlink
