#include <pc/core/stream_session.hpp>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <sstream>

#include <common/nack_reason.hpp>
#include <common/requests.hpp>

namespace qrterm {
namespace {

// "p" in "rad/s" -> "p_rad_per_s": a unit in a column name, in characters every CSV reader takes.
std::string column_name(const Trace& trace) {
  std::string unit;
  for (char c : trace.unit) {
    if (c == '/') {
      unit += "_per_";
    } else if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-') {
      unit += c;
    } else {
      unit += '_';
    }
  }
  return trace.name + "_" + unit;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

void StreamSession::table_unanswered() {
  table_given_up_ = true;
  state_ = "the QR does not answer observable_get: no streams";
  hooks_.note(Severity::warning, "the QR does not answer the observable table request: no plots from this firmware");
}

void StreamSession::stream_unanswered() {
  in_flight_.reset();
  stalled_ = true;
}

void StreamSession::link_up() {
  table_given_up_ = false;
  table_owed_ = true;
  table_asked_ = false;
  stalled_ = false;
  in_flight_.reset();
  // A QR that starts anew runs no stream: what the screens want is asked for again.
  for (uint8_t s = 0; s < kStreams; ++s) asked_[s] = running_[s] = StreamPlan{};
}

void StreamSession::pick(const std::string& names) {
  std::istringstream words(names);
  std::string name;
  bool changed = false;
  while (words >> name) {
    const std::optional<uint8_t> id = catalog_.find(name);
    if (!id) {
      const std::vector<std::string> like = catalog_.names_starting(name.substr(0, 1));
      std::string hint;
      for (const std::string& n : like) hint += (hint.empty() ? "" : ", ") + n;
      hooks_.note(Severity::warning, catalog_.complete()
                                         ? "no observable \"" + name + "\"" + (hint.empty() ? "" : " (" + hint + ")")
                                         : "no observable \"" + name + "\" in the QR's table yet (" + state_ + ")");
      continue;
    }
    if (plot_.traces().size() >= kMaxTraces) {
      hooks_.note(Severity::warning, "the plot has " + std::to_string(kMaxTraces) + " traces already: " + name +
                                         " left out (Backspace removes the last)");
      break;
    }
    if (plot_.add(*id, *catalog_.row(*id))) changed = true;
  }
  if (changed) selection_changed();
}

void StreamSession::remove_last() {
  if (plot_.traces().empty()) return;
  plot_.remove_last();
  selection_changed();
}

void StreamSession::faster() {
  plot_.faster();
  selection_changed();
}

void StreamSession::slower() {
  plot_.slower();
  selection_changed();
}

void StreamSession::selection_changed() {
  plot_.clear_points();
  stalled_ = false;
}

void StreamSession::open_radio() {
  radio_open_ = true;
  radio_.start();
  stalled_ = false;
  radio_state_.clear();
  note_radio_state();
}

void StreamSession::close_radio() {
  radio_open_ = false;
  stalled_ = false;
}

bool StreamSession::lowered() const {
  const bool plot_has_it = !radio_streams() && carried_.empty() && !plot_.traces().empty();
  return download_ && plot_has_it && catalog_.control_hz() != 0 &&
         plot_divider() != plot_.divider(catalog_.control_hz());
}

void StreamSession::download_running(bool running) {
  if (running == download_) return;
  const std::string chosen = plot_rate(plot_.divider(catalog_.control_hz()));
  if (!running && lowered()) hooks_.note(Severity::info, "log download over: the plot's stream back to " + chosen);
  download_ = running;
  stalled_ = false;
  if (running && lowered()) {
    hooks_.note(Severity::info, "the plot's stream lowered to " + plot_rate(plot_divider()) +
                                    " during the log download (" + chosen + " would slow it; back after)");
  }
}

uint16_t StreamSession::plot_divider() const {
  const uint16_t hz = catalog_.control_hz();
  const uint16_t chosen = plot_.divider(hz);
  const uint8_t n = static_cast<uint8_t>(plot_.traces().size());
  if (!download_ || wire::stream_bytes_per_s(hz, chosen, n) <= kDownloadStreamBytesPerS) return chosen;
  // The plot's rates from the fastest down: the first slower than the pilot's that fits.
  uint16_t divider = chosen;
  for (size_t i = std::size(kPlotRatesHz); i-- > 0;) {
    divider = static_cast<uint16_t>(std::clamp<uint32_t>(hz / kPlotRatesHz[i], 1, 65535));
    if (divider > chosen && wire::stream_bytes_per_s(hz, divider, n) <= kDownloadStreamBytesPerS) break;
  }
  return divider;
}

std::string StreamSession::plot_rate(uint16_t divider) const {
  return number(static_cast<double>(catalog_.control_hz()) / divider) + " Hz";
}

std::string StreamSession::cost_text(uint32_t telemetry_hz) const {
  const uint32_t room = wire::stream_room_bytes_per_s(telemetry_hz);
  const size_t n = plot_.traces().size();
  if (n == 0 || catalog_.control_hz() == 0) return "room " + std::to_string(room) + " B/s";
  const uint16_t divider = plot_.divider(catalog_.control_hz());
  const uint32_t bytes = wire::stream_bytes_per_s(catalog_.control_hz(), divider, static_cast<uint8_t>(n));
  const uint32_t samples = wire::stream_samples_per_s(catalog_.control_hz(), divider, static_cast<uint8_t>(n));
  return std::to_string(n) + " x " + std::to_string(catalog_.control_hz() / divider) +
         " Hz = " + std::to_string(samples) + " samples/s: " + std::to_string(bytes) + " of " + std::to_string(room) +
         " B/s" + (bytes > room ? " OVER" : "");
}

StreamPlan StreamSession::wanted(uint8_t stream) const {
  if (radio_streams()) {
    const uint16_t divider = static_cast<uint16_t>(std::max(1, catalog_.control_hz() / kRadioStreamHz));
    const auto first = rc_ids_->begin() + stream * wire::kStreamObservablesMax;
    return StreamPlan{std::vector<uint8_t>(first, first + wire::kStreamObservablesMax), divider};
  }
  if (stream != kPlotStream) return StreamPlan{};
  if (!carried_.empty()) return StreamPlan{carried_, 1};
  if (plot_.traces().empty()) return StreamPlan{};
  return StreamPlan{plot_.ids(), plot_divider()};
}

void StreamSession::note_radio_state() {
  radio_streaming_ = false;
  if (!catalog_.complete()) {
    radio_state_ = "no table yet";
  } else if (!rc_ids_) {
    radio_state_ = "the QR's table has no rc_ch1..rc_ch16: this firmware sends no channels";
  } else {
    uint8_t running = 0;
    for (uint8_t s = 0; s < kStreams; ++s) running += running_[s] == wanted(s) ? 1 : 0;
    radio_streaming_ = running == kStreams;
    if (radio_streaming_) {
      radio_state_ = std::to_string(kRadioChannels) + " channels at " + std::to_string(kRadioStreamHz) + " Hz";
    } else if (radio_state_.rfind("refused", 0) != 0) {
      radio_state_ = "asking the QR (" + std::to_string(running) + " of " + std::to_string(kStreams) + " streams)";
    }
  }
}

void StreamSession::tick(LinkSession& link, uint32_t now_ms) {
  // Rows reach the disk twice a second, not per frame: at 200 frames a second a flush each would
  // cost more than the plot.
  if (csv_file_ && now_ms - flushed_ms_ >= 500) {
    csv_file_->flush();
    flushed_ms_ = now_ms;
  }
  if (table_given_up_) return;
  if (!catalog_.complete()) {
    state_ = "no table yet (" + std::to_string(catalog_.complete_rows()) + "/" +
             (catalog_.count() ? std::to_string(catalog_.count()) : std::string("?")) + ")";
    if (table_owed_ || (table_asked_ && now_ms - table_asked_ms_ >= kTableRetryMs)) {
      link.request(wire::ObservableGet{0, wire::kAllObservables}, now_ms);
      table_owed_ = false;
      table_asked_ = true;
      table_asked_ms_ = now_ms;
    }
    return;
  }
  if (state_.rfind("no table", 0) == 0) state_ = "table of " + std::to_string(catalog_.count()) + " observables";
  if (!rc_ids_) {
    std::vector<uint8_t> ids;
    for (uint8_t ch = 1; ch <= kRadioChannels; ++ch) {
      if (const std::optional<uint8_t> id = catalog_.find("rc_ch" + std::to_string(ch))) ids.push_back(*id);
    }
    if (ids.size() == kRadioChannels) rc_ids_ = ids;
  }
  if (radio_open_) note_radio_state();
  if (in_flight_ || stalled_ || catalog_.control_hz() == 0) return;
  for (uint8_t s = 0; s < kStreams; ++s) {
    const StreamPlan plan = wanted(s);
    if (plan != asked_[s]) return ask(link, s, plan, now_ms);
  }
}

void StreamSession::ask(LinkSession& link, uint8_t stream, const StreamPlan& plan, uint32_t now_ms) {
  wire::StreamRequest request;
  request.stream = stream;
  request.divider = plan.divider;
  for (size_t i = 0; i < plan.ids.size(); ++i) request.id[i] = plan.ids[i];
  asked_[stream] = plan;
  in_flight_.emplace(stream, plan);
  if (stream == kPlotStream && !radio_streams()) state_ = plan.ids.empty() ? "stopping" : "asking the QR";
  link.request(request, now_ms);
}

void StreamSession::on_answer(wire::MessageType type, wire::NackReason reason, uint32_t telemetry_hz) {
  if (type == wire::MessageType::observable_get) {
    if (reason != wire::NackReason::none) hooks_.note(Severity::warning, "QR refused the observable table request");
    return;
  }
  if (type != wire::MessageType::stream_request || !in_flight_) return;
  const auto [stream, plan] = *in_flight_;
  in_flight_.reset();
  answered(stream, plan, reason, telemetry_hz);
}

void StreamSession::answered(uint8_t stream, const StreamPlan& plan, wire::NackReason reason, uint32_t telemetry_hz) {
  const bool radio = radio_streams() && plan == wanted(stream);
  if (reason != wire::NackReason::none) {
    const wire::NackReasonSpec* spec = wire::find_nack_reason(reason);
    const std::string refused = std::string("refused: ") + (spec != nullptr ? spec->name : "?");
    const std::string why = spec != nullptr ? spec->text : "refused";
    if (radio) {
      radio_state_ = refused;
      hooks_.note(Severity::warning, "QR refused the radio's channels: " + why);
    } else if (stream == kPlotStream) {
      state_ = refused;
      hooks_.note(Severity::warning, "QR refused the stream: " + why + " (" + cost_text(telemetry_hz) + ")");
    }
    return;
  }
  running_[stream] = plan;
  unpackers_[stream].start(static_cast<uint8_t>(plan.ids.size()));
  if (radio) return note_radio_state();
  if (stream != kPlotStream || radio_streams()) return;
  if (!carried_.empty() && plan.ids == carried_) {
    state_ = "carrying autotune's identification";
    return;
  }
  if (plan.divider == 0) {
    state_ = "stopped";
    return;
  }
  state_ = lowered() && plan.divider == plot_divider()
               ? "streaming at " + plot_rate(plan.divider) + " during the download"
               : "streaming";
  open_csv();
}

void StreamSession::open_csv() {
  csv_.reset();
  csv_file_.reset();
  if (!hooks_.open) return;
  csv_file_ = hooks_.open("observables_" + std::to_string(++csv_count_) + ".csv");
  if (!csv_file_) return;
  std::vector<std::string> header = {"time_s", "qr_time_s"};
  for (const Trace& t : plot_.traces()) header.push_back(column_name(t));
  csv_.emplace(*csv_file_, header);
}

void StreamSession::on(const wire::ObservableSamples& m, double now_s) {
  // Frames of an older plan, or before the QR said yes, are not the screens'.
  const uint8_t stream = m.stream();
  if (stream >= kStreams || (in_flight_ && in_flight_->first == stream)) return;
  const StreamPlan plan = wanted(stream);
  if (plan.divider == 0 || running_[stream] != plan) return;
  if (radio_streams()) {
    const size_t first = size_t{stream} * wire::kStreamObservablesMax;
    unpackers_[stream].unpack(m, [&](const int16_t* bits) {
      for (size_t i = 0; i < plan.ids.size(); ++i)
        radio_.on_channel(static_cast<uint8_t>(first + i), static_cast<uint16_t>(bits[i]));
    });
    return;
  }
  if (stream != kPlotStream) return;
  if (!carried_.empty()) return on_carried_samples(m);
  on_plot_samples(m, now_s);
}

void StreamSession::on_carried_samples(const wire::ObservableSamples& m) {
  wire::SampleUnpacker& unpacker = unpackers_[kPlotStream];
  std::vector<std::vector<double>> samples;
  unpacker.unpack(m, [&](const int16_t* bits) {
    std::vector<double> values;
    for (size_t i = 0; i < carried_.size(); ++i) {
      const ObservableRow* row = catalog_.row(carried_[i]);
      values.push_back(row != nullptr ? row->value(bits[i]) : 0.0);
    }
    samples.push_back(std::move(values));
  });
  // The frame's samples are the newest; their numbers follow from the frames' counter.
  const uint32_t first_index = unpacker.received() + unpacker.lost() - static_cast<uint32_t>(samples.size());
  for (size_t j = 0; j < samples.size(); ++j) {
    ++received_;
    if (hooks_.carried) hooks_.carried(carried_, first_index + static_cast<uint32_t>(j), samples[j]);
  }
}

void StreamSession::on_plot_samples(const wire::ObservableSamples& m, double now_s) {
  wire::SampleUnpacker& unpacker = unpackers_[kPlotStream];
  const std::vector<Trace>& traces = plot_.traces();
  // The plan the QR runs: the pilot's rate, or the lowered one during a download.
  const double period_s = static_cast<double>(running_[kPlotStream].divider) / catalog_.control_hz();
  std::vector<std::vector<double>> samples;
  unpacker.unpack(m, [&](const int16_t* bits) {
    std::vector<double> values;
    for (size_t i = 0; i < traces.size(); ++i) {
      const ObservableRow* row = catalog_.row(traces[i].id);
      values.push_back(row != nullptr ? row->value(bits[i]) : 0.0);
    }
    samples.push_back(std::move(values));
  });
  // The newest sample of the frame was taken last; the others a period apart before it.
  const uint32_t first_index = unpacker.received() + unpacker.lost() - static_cast<uint32_t>(samples.size());
  for (size_t j = 0; j < samples.size(); ++j) {
    const double t = now_s - static_cast<double>(samples.size() - 1 - j) * period_s;
    plot_.add_sample(t, samples[j]);
    ++received_;
    if (csv_) {
      CsvRow row;
      row << number(t) << number(static_cast<double>(first_index + j) * period_s);
      for (double v : samples[j]) row << number(v);
      csv_->write(row);
    }
  }
  last_arrival_s_ = now_s;
}

}  // namespace qrterm
