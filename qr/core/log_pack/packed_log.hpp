// The log's lines packed in the board's log area (line_coder.hpp), with an index of keyframes: a
// reader starts at the keyframe at or before the line it wants and unpacks forward from there
// (LogCursor), a bounded number of lines a call, so a download or a part asked for again never
// holds up a tick for long.
//
// The index lives beside the area, not in it: its size is taken from the area's bytes, so the log
// uses exactly the memory the board gives it.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <qr/core/log_pack/line_coder.hpp>

namespace qr::log_pack {

inline constexpr uint32_t kMaxLines = 0xFFFF;  // line numbers are u16 on the wire
inline constexpr size_t kMaxKeyframes = (kMaxLines + kKeyframeLines - 1) / kKeyframeLines;

template <class Model>
class PackedLog {
 public:
  static constexpr uint32_t kNominalSensorBits = 64, kNominalTelemetryBits = 96;
  static constexpr size_t kIndexBytes = sizeof(Keyframe<Model>[kMaxKeyframes]) + sizeof(size_t[kMaxKeyframes]);

  // Cold, out of line: the index's initialisation is a loop once at power-up, not code spread
  // through the Flight's constructor.
  [[gnu::cold, gnu::noinline]] PackedLog() {}

  void attach(uint8_t* area, size_t bytes) {
    area_ = area;
    bytes_ = area == nullptr || bytes <= kIndexBytes ? 0 : bytes - kIndexBytes;
    clear(contents_);
  }
  [[gnu::cold, gnu::noinline]] void clear(Contents contents) {
    contents_ = contents;
    lines_ = telemetry_lines_ = 0;
    end_bit_ = 0;
    full_ = false;
    coder_.reset();
  }

  // Appends a line; `take(model)` brings the model in step with the chain at a keyframe. False,
  // and nothing kept, when the line does not fit: the log is full from then on (the coder's state
  // moved with the line it could not keep).
  template <class Take>
  [[gnu::noinline]] bool append(LogLine line, Take&& take) {
    if (full_ || bytes_ == 0 || lines_ >= kMaxLines) {
      full_ = true;
      return false;
    }
    if (lines_ % kKeyframeLines == 0) {
      take(coder_.model());
      Keyframe<Model>& k = keyframes_[lines_ / kKeyframeLines];
      coder_.keep(k);
      coder_.start(k);
      keyframe_bits_[lines_ / kKeyframeLines] = end_bit_;
    }
    LineIo out = LineIo::packing(area_, bytes_, end_bit_);
    coder_.code(out, line, contents_, lines_);
    if (!out.ok()) {
      full_ = true;
      return false;
    }
    end_bit_ = out.bit();
    if (line.has_telemetry) ++telemetry_lines_;
    ++lines_;
    return true;
  }

  uint16_t lines() const { return static_cast<uint16_t>(lines_); }
  uint16_t telemetry_lines() const { return static_cast<uint16_t>(telemetry_lines_); }
  Contents contents() const { return contents_; }
  size_t bytes() const { return bytes_; }
  size_t bits_used() const { return end_bit_; }
  bool full() const { return full_; }
  // The lines the area would hold at the bits a line took so far; before the first, at what a
  // hover's lines took (LogCapacity: 60 bits of sensor record at 1 kHz; telemetry at 100 Hz 90).
  [[gnu::cold, gnu::noinline]] uint16_t capacity_estimate() const {
    if (bytes_ == 0) return 0;
    if (full_) return lines();
    const uint64_t bits = uint64_t{bytes_} * 8u;
    const uint64_t nominal = (contents_.sensor ? kNominalSensorBits : 0u) +
                             (contents_.telemetry ? kNominalTelemetryBits / contents_.telemetry_every : 0u);
    if (lines_ == 0)
      return static_cast<uint16_t>(nominal == 0 || bits / nominal > kMaxLines ? kMaxLines : bits / nominal);
    const uint64_t estimate = lines_ + (bits - end_bit_) * lines_ / end_bit_;
    return static_cast<uint16_t>(estimate > kMaxLines ? kMaxLines : estimate);
  }

  // For LogCursor: the area and the keyframe at or before line `index`.
  const uint8_t* area() const { return area_; }
  const Keyframe<Model>& keyframe(uint32_t index) const { return keyframes_[index / kKeyframeLines]; }
  size_t keyframe_bit(uint32_t index) const { return keyframe_bits_[index / kKeyframeLines]; }

 private:
  uint8_t* area_ = nullptr;
  size_t bytes_ = 0;
  Contents contents_{};
  uint32_t lines_ = 0;
  uint32_t telemetry_lines_ = 0;
  size_t end_bit_ = 0;
  bool full_ = false;
  LineCoder<Model> coder_{};
  Keyframe<Model> keyframes_[kMaxKeyframes] = {};
  size_t keyframe_bits_[kMaxKeyframes] = {};
};

// Reads a PackedLog's lines by their index (the sensor log's line number; LogCursor::index_of
// gives a telemetry line's).
template <class Model>
class LogCursor {
 public:
  [[gnu::cold, gnu::noinline]] LogCursor() {}

  static uint32_t index_of(Contents c, bool telemetry, uint16_t line) {
    return telemetry ? uint32_t{line} * c.telemetry_every : line;
  }

  // Moves towards line `index`, unpacking at most `budget` lines: true when line() is that line.
  // A cursor past the line, or before the line's keyframe, starts again at that keyframe. Cold: it
  // runs in downloads, on the ground, and is kept small on the QR.
  [[gnu::cold]] bool reach(const PackedLog<Model>& log, uint32_t index, uint16_t budget) {
    if (index >= log.lines()) return false;
    const uint32_t keyframe = index / kKeyframeLines * kKeyframeLines;
    if (!started_ || next_ > index + 1 || next_ < keyframe) {
      next_ = keyframe;
      started_ = true;
    }
    for (; next_ <= index && budget > 0; --budget) {
      if (next_ % kKeyframeLines == 0) {  // where the packing started afresh
        coder_.start(log.keyframe(next_));
        bit_ = log.keyframe_bit(next_);
      }
      LineIo in = LineIo::unpacking(log.area(), log.bytes(), bit_);
      coder_.code(in, line_, log.contents(), next_);
      bit_ = in.bit();
      ++next_;
    }
    return next_ == index + 1;
  }
  const LogLine& line() const { return line_; }
  void forget() { started_ = false; }

 private:
  LineCoder<Model> coder_{};
  LogLine line_{};
  size_t bit_ = 0;
  uint32_t next_ = 0;  // the index of the next line to unpack
  bool started_ = false;
};

}  // namespace qr::log_pack
