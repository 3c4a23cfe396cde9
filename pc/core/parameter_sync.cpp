#include <pc/core/parameter_sync.hpp>

#include <algorithm>

#include <common/requests.hpp>
#include <pc/core/param_file.hpp>

namespace qrterm {
namespace {

uint8_t id_byte(wire::ParamId id) { return static_cast<uint8_t>(id); }

// Ids are 1..kParameterCount in table order (the wire's parameter table test checks it).
size_t row_of(wire::ParamId id) { return static_cast<size_t>(id_byte(id)) - 1; }

}  // namespace

std::string param_text(wire::ParamId id, int32_t raw) {
  const wire::ParameterSpec* spec = wire::find_parameter(id_byte(id));
  return std::string(spec->name) + " = " + format_real(*spec, raw);
}

std::optional<int32_t> ParameterSync::reported(wire::ParamId id) const {
  const size_t row = row_of(id);
  return row < wire::kParameterCount ? reported_[row] : std::nullopt;
}

void ParameterSync::queue(wire::ParamId id) {
  if (std::find(queue_.begin(), queue_.end(), id) == queue_.end()) queue_.push_back(id);
}

bool ParameterSync::on_its_way(wire::ParamId id) const {
  return in_flight_ == id || std::find(queue_.begin(), queue_.end(), id) != queue_.end();
}

void ParameterSync::send_all() {
  for (const wire::ParameterSpec& spec : wire::kParameterTable) queue(spec.id);
  announced_ = false;
}

void ParameterSync::step(const GainStep& step) {
  ++steps_taken_;
  if (burst_ && burst_->id != step.id) end_steps();
  const int32_t before = wanted_.get(step.id);
  const int32_t after = stepped(step, before);
  if (after == before) {
    end_steps();
    note_(Severity::warning, param_text(step.id, before) + " is at the end of its range");
    return;
  }
  if (!burst_) burst_ = StepBurst{step.id, before, 0, now_ms_};
  ++burst_->steps;
  burst_->last_ms = now_ms_;
  wanted_.set(id_byte(step.id), after);
  queue(step.id);
}

void ParameterSync::end_steps() {
  if (!burst_) return;
  const StepBurst burst = *burst_;
  burst_.reset();
  const int32_t now = wanted_.get(burst.id);
  if (burst.steps == 1) return note_(Severity::info, param_text(burst.id, now));
  const wire::ParameterSpec* spec = wire::find_parameter(id_byte(burst.id));
  note_(Severity::info, param_text(burst.id, now) + " (" + format_real(*spec, burst.from) + " -> " +
                            format_real(*spec, now) + " in " + std::to_string(burst.steps) + " steps)");
}

void ParameterSync::settle_steps(uint32_t now_ms) {
  now_ms_ = now_ms;
  if (burst_ && now_ms - burst_->last_ms >= kStepsSettleMs) end_steps();
}

wire::NackReason ParameterSync::set(wire::ParamId id, int32_t raw) {
  const wire::NackReason reason = wanted_.set(id_byte(id), raw);
  if (reason != wire::NackReason::none) return reason;
  note_(Severity::info, param_text(id, raw));
  queue(id);
  return reason;
}

void ParameterSync::on_report(const wire::ParamReport& report) {
  take_report(report);
  count_read_back(report);
}

void ParameterSync::take_report(const wire::ParamReport& report) {
  const wire::ParameterSpec* spec = wire::find_parameter(report.id);
  if (spec == nullptr) return;
  std::optional<int32_t>& reported = reported_[row_of(spec->id)];
  const bool news = reported != report.value;
  reported = report.value;
  // A difference while a value is on its way is the upload not done yet; after it, the QR holds
  // something the pilot did not ask for (it refused it, or changed it itself).
  const int32_t wanted = wanted_.get(spec->id);
  if (news && !on_its_way(spec->id) && report.value != wanted && wire::written_by_qr(spec->id)) {
    wanted_.set(report.id, report.value);
    note_(Severity::info, "the QR set " + param_text(spec->id, report.value) + ", and so does the console");
    return;
  }
  if (news && !on_its_way(spec->id) && report.value != wanted) {
    note_(Severity::warning,
          "the QR has " + param_text(spec->id, report.value) + ", the console " + format_real(*spec, wanted));
  }
}

void ParameterSync::read_back(LinkSession& link, uint32_t now_ms) {
  link.request(wire::ParamGet{0, wire::kAllParameters}, now_ms);
  read_back_left_ = wire::kParameterCount;
  read_back_differ_.clear();
}

// After take_report: a value the QR changed itself (and the console took) is no difference.
void ParameterSync::count_read_back(const wire::ParamReport& report) {
  if (read_back_left_ == 0) return;
  const wire::ParameterSpec* spec = wire::find_parameter(report.id);
  if (spec != nullptr && report.value != wanted_.get(spec->id)) read_back_differ_.push_back(spec->name);
  if (--read_back_left_ > 0) return;
  if (read_back_differ_.empty()) {
    note_(Severity::info,
          std::to_string(wire::kParameterCount) + " parameters read back: the QR has the console's values");
    return;
  }
  std::string names;
  for (const std::string& n : read_back_differ_) names += (names.empty() ? "" : ", ") + n;
  note_(Severity::warning, "parameters read back: the QR differs in " + names + " (the parameter screen shows them)");
}

void ParameterSync::tick(LinkSession& link, uint32_t now_ms) {
  if (!link.pending(wire::MessageType::param_set)) in_flight_.reset();
  if (in_flight_) return;
  if (!queue_.empty()) {
    if (!announced_ && queue_.size() > 1)
      note_(Severity::info, "sending " + std::to_string(queue_.size()) + " parameters");
    announced_ = true;
    in_flight_ = queue_.front();
    queue_.pop_front();
    link.request(wire::ParamSet{0, id_byte(*in_flight_), wanted_.get(*in_flight_)}, now_ms);
    read_back_owed_ = true;
  } else if (read_back_owed_) {
    read_back_owed_ = false;
    link.request(wire::ParamGet{0, wire::kAllParameters}, now_ms);
  }
}

}  // namespace qrterm
