// The QR's observable table as it sends it, for the console's tests: per row its info, then
// "name unit" in pieces of 7 with a NUL at the end. `Sink` takes both (the catalog, a session).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <string>

#include <common/messages.hpp>

namespace qrterm {

template <class Sink>
void send_observable_table(Sink& sink) {
  for (const wire::ObservableSpec& spec : wire::kObservableTable) {
    const uint8_t id = static_cast<uint8_t>(spec.id);
    sink.on(wire::ObservableInfo{id, wire::kObservableCount, spec.type, spec.scale, 1000});
    const std::string text = std::string(spec.name) + " " + spec.unit;
    for (uint8_t part = 0; part * 7u <= text.size(); ++part) {
      wire::ObservableText piece;
      piece.id = id;
      piece.part = part;
      for (size_t i = 0; i < 7 && part * 7u + i < text.size(); ++i) piece.text[i] = text[part * 7u + i];
      sink.on(piece);
    }
  }
}

}  // namespace qrterm
