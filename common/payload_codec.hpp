// Serialising message structs: each message lists its fields once, in wire order, in a static
// `fields(self, visit)` function; the writer, the reader and the size counter below are visitors
// over that list. Multi-byte integers go little-endian, one byte at a time, so the layout never
// depends on the compiler's struct padding or the CPU's byte order.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/frame.hpp>

namespace wire {

template <class T>
concept WireEnum = __is_enum(T);

template <class E>
using underlying_t = __underlying_type(E);

class PayloadWriter {
 public:
  constexpr PayloadWriter(uint8_t* out, size_t capacity) : out_(out), capacity_(capacity) {}

  constexpr void operator()(uint8_t v) { put(v); }
  constexpr void operator()(char v) { put(static_cast<uint8_t>(v)); }
  constexpr void operator()(int8_t v) { put(static_cast<uint8_t>(v)); }
  constexpr void operator()(uint16_t v) {
    put(static_cast<uint8_t>(v));
    put(static_cast<uint8_t>(v >> 8));
  }
  constexpr void operator()(int16_t v) { (*this)(static_cast<uint16_t>(v)); }
  constexpr void operator()(uint32_t v) {
    for (int shift = 0; shift < 32; shift += 8) put(static_cast<uint8_t>(v >> shift));
  }
  constexpr void operator()(int32_t v) { (*this)(static_cast<uint32_t>(v)); }
  template <WireEnum E>
  constexpr void operator()(E v) {
    (*this)(static_cast<underlying_t<E>>(v));
  }
  template <class T, size_t N>
  constexpr void operator()(const T (&array)[N]) {
    for (const T& element : array) (*this)(element);
  }

  constexpr size_t size() const { return size_; }
  constexpr bool overflowed() const { return overflowed_; }

 private:
  constexpr void put(uint8_t byte) {
    if (size_ < capacity_) {
      out_[size_++] = byte;
    } else {
      overflowed_ = true;
    }
  }

  uint8_t* out_;
  size_t capacity_;
  size_t size_ = 0;
  bool overflowed_ = false;
};

class PayloadReader {
 public:
  constexpr PayloadReader(const uint8_t* in, size_t length) : in_(in), length_(length) {}

  constexpr void operator()(uint8_t& v) { v = get(); }
  constexpr void operator()(char& v) { v = static_cast<char>(get()); }
  constexpr void operator()(int8_t& v) { v = static_cast<int8_t>(get()); }
  constexpr void operator()(uint16_t& v) {
    const uint8_t low = get();
    v = static_cast<uint16_t>(low | (get() << 8));
  }
  constexpr void operator()(int16_t& v) {
    uint16_t raw = 0;
    (*this)(raw);
    v = static_cast<int16_t>(raw);
  }
  constexpr void operator()(uint32_t& v) {
    v = 0;
    for (int shift = 0; shift < 32; shift += 8) v |= static_cast<uint32_t>(get()) << shift;
  }
  constexpr void operator()(int32_t& v) {
    uint32_t raw = 0;
    (*this)(raw);
    v = static_cast<int32_t>(raw);
  }
  template <WireEnum E>
  constexpr void operator()(E& v) {
    underlying_t<E> raw{};
    (*this)(raw);
    v = static_cast<E>(raw);
  }
  template <class T, size_t N>
  constexpr void operator()(T (&array)[N]) {
    for (T& element : array) (*this)(element);
  }

  // True when exactly the whole input was read: no more, no less.
  constexpr bool consumed_exactly() const { return !underrun_ && position_ == length_; }

 private:
  constexpr uint8_t get() {
    if (position_ < length_) return in_[position_++];
    underrun_ = true;
    return 0;
  }

  const uint8_t* in_;
  size_t length_;
  size_t position_ = 0;
  bool underrun_ = false;
};

// Counts wire bytes without writing them, at compile time.
class SizeCounter {
 public:
  constexpr void operator()(uint8_t) { size_ += 1; }
  constexpr void operator()(char) { size_ += 1; }
  constexpr void operator()(int8_t) { size_ += 1; }
  constexpr void operator()(uint16_t) { size_ += 2; }
  constexpr void operator()(int16_t) { size_ += 2; }
  constexpr void operator()(uint32_t) { size_ += 4; }
  constexpr void operator()(int32_t) { size_ += 4; }
  template <WireEnum E>
  constexpr void operator()(E) {
    (*this)(underlying_t<E>{});
  }
  template <class T, size_t N>
  constexpr void operator()(const T (&array)[N]) {
    for (const T& element : array) (*this)(element);
  }
  constexpr size_t size() const { return size_; }

 private:
  size_t size_ = 0;
};

// Anything with a field list can be measured; messages and log records both are.
template <class Record>
constexpr size_t wire_size() {
  const Record record{};
  SizeCounter counter;
  Record::fields(record, counter);
  return counter.size();
}

// Writes a record's fields to `out`; returns the number of bytes (capacity must suffice).
template <class Record>
constexpr size_t write_fields(const Record& record, uint8_t* out, size_t capacity) {
  PayloadWriter writer(out, capacity);
  Record::fields(record, writer);
  return writer.overflowed() ? 0 : writer.size();
}

// Reads a record from exactly `length` bytes and accepts it only if every field is in range.
template <class Record>
constexpr bool read_fields(const uint8_t* in, size_t length, Record& out) {
  Record record{};
  PayloadReader reader(in, length);
  Record::fields(record, reader);
  if (!reader.consumed_exactly() || !record.valid()) return false;
  out = record;
  return true;
}

// A message is a record with a type in the table whose payload length matches its fields.
template <class Msg>
concept Message = requires {
  Msg::kType;
}
&&message_spec(Msg::kType) != nullptr&& message_spec(Msg::kType)->payload_length == wire_size<Msg>();

template <Message Msg>
FrameBytes encode(const Msg& message) {
  uint8_t payload[kMaxPayloadBytes] = {};
  const size_t length = write_fields(message, payload, sizeof payload);
  return make_frame(Msg::kType, payload, length);
}

// Decodes a frame into a typed message: the type must match, the payload must be exactly the
// message's length and every field in its documented range.
template <Message Msg>
bool decode(const Frame& frame, Msg& out) {
  if (frame.type != Msg::kType) return false;
  return read_fields(frame.payload, frame.length, out);
}

}  // namespace wire
