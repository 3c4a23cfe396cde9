// Fuzz target: the console's decoders of observable streams (docs/protocol.md section 13) fed an
// arbitrary QR -> PC byte stream: the frame parser, the observable table assembled from
// observable_info and observable_text, and each stream's samples unpacked. A row the catalog
// calls complete has a name without a space and is found by that name; an unpacked frame gives
// whole samples of the stream's width, never more than a frame holds.
#include <stddef.h>
#include <stdint.h>

#include <string>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/sample_packing.hpp>
#include <pc/core/observable_catalog.hpp>

namespace {

void require(bool condition) {
  if (!condition) __builtin_trap();
}

struct Receiver {
  qrterm::ObservableCatalog& catalog;
  wire::SampleUnpacker (&streams)[wire::kStreamCount];

  void operator()(const wire::ObservableInfo& m) { catalog.on(m); }
  void operator()(const wire::ObservableText& m) { catalog.on(m); }
  void operator()(const wire::ObservableSamples& m) {
    wire::SampleUnpacker& unpacker = streams[m.stream()];
    uint8_t samples = 0;
    const uint8_t given = unpacker.unpack(m, [&](const int16_t* values) {
      require(values >= m.value && values + unpacker.observables() <= m.value + wire::kSampleValuesPerFrame);
      ++samples;
    });
    require(given == samples && samples == wire::samples_per_frame(unpacker.observables()));
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  qrterm::ObservableCatalog catalog;
  wire::SampleUnpacker streams[wire::kStreamCount];
  // The first byte says how wide each stream is: two bits each, 1..4 observables.
  for (uint8_t s = 0; s < wire::kStreamCount; ++s)
    streams[s].start(static_cast<uint8_t>(((data[0] >> (2 * s)) & 3) + 1));
  wire::FrameParser parser(wire::Listen::qr_to_pc);
  Receiver receiver{catalog, streams};
  for (size_t i = 1; i < size; ++i) parser.push(data[i], [&](const wire::Frame& f) { wire::dispatch(f, receiver); });

  for (uint8_t id = 0; id < 255; ++id) {
    const qrterm::ObservableRow* row = catalog.row(id);
    if (row == nullptr) continue;
    require(row->name.find(' ') == std::string::npos && !row->name.empty());
    require(catalog.find(row->name).has_value());
  }
  require(catalog.complete_rows() <= catalog.count());
  return 0;
}
