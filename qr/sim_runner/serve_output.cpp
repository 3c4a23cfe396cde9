#include <qr/sim_runner/serve_output.hpp>

#include <errno.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

#include <common/message_table.hpp>

namespace qrsim {

void ServeOutput::put(uint8_t byte) {
  if (partial_.size == 0) {
    if (byte != wire::kStartByte) return queue(Unit{{byte}, 1});
    partial_.bytes[partial_.size++] = byte;
    return;
  }
  if (partial_.size == 1) {
    const wire::MessageSpec* spec = wire::find_message(byte);
    if (spec == nullptr || spec->direction != wire::Direction::qr_to_pc) {
      // The 'M' started no frame the QR sends: it goes alone, and this byte is looked at afresh.
      partial_.size = 0;
      queue(Unit{{wire::kStartByte}, 1});
      return put(byte);
    }
    partial_length_ = wire::frame_length(*spec);
  }
  partial_.bytes[partial_.size++] = byte;
  if (partial_.size == partial_length_) {
    queue(partial_);
    partial_.size = 0;
    partial_length_ = 0;
  }
}

void ServeOutput::finish() {
  if (partial_.size > 0) queue(partial_);
  partial_.size = 0;
  partial_length_ = 0;
}

void ServeOutput::queue(const Unit& unit) {
  // Room for it: the oldest frames not yet begun make way (a begun one is finished first).
  while (queued_bytes_ + unit.size > kQueueBytes) {
    const size_t oldest = head_written_ > 0 ? 1 : 0;
    if (oldest >= units_.size()) break;
    drop(oldest);
  }
  units_.push_back(unit);
  queued_bytes_ += unit.size;
}

void ServeOutput::drop(size_t index) {
  ++frames_dropped_;
  bytes_dropped_ += units_[index].size;
  queued_bytes_ -= units_[index].size;
  if (index == 0) head_written_ = 0;
  units_.erase(units_.begin() + static_cast<std::ptrdiff_t>(index));
}

void ServeOutput::write_to(int fd) {
  while (!units_.empty()) {
    // As many queued bytes as one write takes, the rest of a begun frame first.
    uint8_t buffer[kQueueBytes + wire::kMaxFrameBytes];
    size_t count = 0;
    size_t offset = head_written_;
    for (const Unit& unit : units_) {
      if (count + unit.size - offset > sizeof buffer) break;
      std::memcpy(buffer + count, unit.bytes + offset, unit.size - offset);
      count += unit.size - offset;
      offset = 0;
    }
    const ssize_t n = ::write(fd, buffer, count);
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return;  // full: the next period tries again
      while (!units_.empty()) drop(0);
      return;
    }
    // Take off what went.
    for (size_t done = static_cast<size_t>(n); done > 0;) {
      const size_t rest = units_.front().size - head_written_;
      if (done < rest) {
        head_written_ = static_cast<uint8_t>(head_written_ + done);
        break;
      }
      done -= rest;
      queued_bytes_ -= units_.front().size;
      units_.pop_front();
      head_written_ = 0;
      ++frames_written_;
    }
    if (static_cast<size_t>(n) < count) return;  // it took only some: full for now
  }
}

}  // namespace qrsim
