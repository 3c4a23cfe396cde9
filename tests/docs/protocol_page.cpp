#include "protocol_page.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

namespace protocol_page {
namespace {

// The page writes minus as U+2212 in prose ("0..N−1", "−4"); a client reads both.
const std::string kMinus = "(?:-|\xE2\x88\x92)";
const std::string kNumber = "(" + kMinus + "?\\d+)";

long long number(std::string text) {
  const std::string unicode_minus = "\xE2\x88\x92";
  if (text.rfind(unicode_minus, 0) == 0) text = "-" + text.substr(unicode_minus.size());
  return std::stoll(text);
}

std::string at(int line) { return "docs/protocol.md:" + std::to_string(line) + ": "; }

// Removes every match of `pattern` from `text`, calling `take` with each: what is left of a cell
// must then state no range (see leftover_range).
template <class Take>
void consume(std::string& text, const std::regex& pattern, Take&& take) {
  std::string rest;
  auto from = text.cbegin();
  for (std::sregex_iterator it(text.begin(), text.end(), pattern), end; it != end; ++it) {
    rest.append(from, (*it)[0].first);
    rest += ' ';
    from = (*it)[0].second;
    take(*it);
  }
  rest.append(from, text.cend());
  text = rest;
}

// Words that state a limit. One left in a cell after the forms below were taken out is a range the
// reader does not understand, and so one nothing would check: the row fails instead.
bool leftover_range(const std::string& rest, std::string& what) {
  static const std::regex kLimit(
      R"((\.\.|≤|≥|<|>|\bbits?\b|\branges?\b|\bsaturated at\b|\bat (most|least)\b|\bbetween\b|\bno (more|less) than\b|\bor (more|less)\b))");
  std::smatch m;
  if (!std::regex_search(rest, m, kLimit)) return false;
  what = m[0].str();
  return true;
}

// The "unit / range" cell of a row: the forms the page uses to state a range.
Range read_range(const std::string& cell, const std::string& own_name, int line, std::vector<std::string>& errors) {
  Range r;
  std::string text = cell;
  const auto fail = [&](const std::string& why) { errors.push_back(at(line) + why + ": " + cell); };

  consume(text, std::regex(R"(\+1 per [a-z_]+ frame \(wraps\))"), [&](const std::smatch&) { r.counter = true; });
  // What this firmware sends, while a client must take more (a later firmware's tasks).
  consume(text, std::regex(R"(\ba client takes any number\b)"), [&](const std::smatch&) { r.sender_only = true; });
  consume(text, std::regex("`0x00` only as padding"), [&](const std::smatch&) { r.nul_padding = true; });
  consume(text, std::regex(R"(\ban acked type\b)"), [&](const std::smatch&) { r.acked_type = true; });
  consume(text, std::regex(R"(\bwithin the parameter's range\b)"),
          [&](const std::smatch&) { r.parameter_range = true; });
  consume(text, std::regex(R"(\bas (?:in )?([a-z]+_[a-z_]+)\b)"),
          [&](const std::smatch& m) { r.same_as = m[1].str(); });
  // "0..4 (sensor), 0..6 (telemetry)": a table two messages share.
  consume(text, std::regex(kNumber + R"(\.\.)" + kNumber + R"( \(([a-z]+)\))"), [&](const std::smatch& m) {
    r.for_message[m[3].str()] = {number(m[1].str()), number(m[2].str())};
  });
  // "0..N−1", "0..count−1": below a number named elsewhere.
  consume(text, std::regex("0\\.\\.([A-Za-z_]+)" + kMinus + "1\\b"),
          [&](const std::smatch& m) { r.below = m[1].str(); });
  int ranges = 0;
  consume(text, std::regex(kNumber + R"(\.\.)" + kNumber), [&](const std::smatch& m) {
    ++ranges;
    r.min = number(m[1].str());
    r.max = number(m[2].str());
  });
  if (ranges > 1) fail("two ranges for one field");
  if (r.min && r.max && *r.min > *r.max) fail("a range that ends before it starts");
  consume(text, std::regex(R"(\bsaturated at (\d+))"), [&](const std::smatch& m) {
    const long long top = number(m[1].str());
    r.max = r.max ? std::min(*r.max, top) : top;
  });
  consume(text, std::regex(R"((?:\b([a-z_]+) )?≤ ([a-z_]+)\b)"), [&](const std::smatch& m) {
    if (m[1].matched && m[1].str() != own_name) fail("a bound on another field than the row's");
    r.at_most = m[2].str();
  });
  // "bits 7–6: the stream": a byte cut into fields, every value of which means something.
  consume(text, std::regex(R"(\bbits \d+(?:–|-)\d+\b)"), [](const std::smatch&) {});
  bool other_bits_zero = false;
  consume(text, std::regex(R"(\bother bits 0( \(ignore them\))?)"), [&](const std::smatch& m) {
    other_bits_zero = true;
    r.sender_only = r.sender_only || m[1].matched;
  });
  uint32_t listed = 0;
  consume(text, std::regex(R"(\bbit (\d+)\b)"), [&](const std::smatch& m) {
    const long long bit = number(m[1].str());
    if (bit < 0 || bit > 31) fail("no such bit");
    else listed |= 1u << bit;
  });
  if (listed != 0 && !other_bits_zero) fail("bits listed, but not what the other bits are (\"other bits 0\")");
  if (other_bits_zero && listed == 0) fail("\"other bits 0\" with no bit listed");
  if (listed != 0) r.bits = listed;

  std::string what;
  if (leftover_range(text, what)) fail("a range the reader does not understand ('" + what + "')");
  return r;
}

std::optional<Scalar> read_scalar(const std::string& text) {
  if (text.size() < 2 || (text[0] != 'u' && text[0] != 'i')) return std::nullopt;
  const std::string width = text.substr(1);
  Scalar s;
  s.is_signed = text[0] == 'i';
  if (width == "8") s.bytes = 1;
  else if (width == "16") s.bytes = 2;
  else if (width == "32") s.bytes = 4;
  else return std::nullopt;
  return s;
}

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> names;
  std::stringstream in(text);
  for (std::string name; std::getline(in, name, ',');) {
    name.erase(0, name.find_first_not_of(' '));
    names.push_back(name);
  }
  return names;
}

// The heading a table belongs to: the nearest paragraph above it that starts in bold.
void read_heading(const std::vector<std::string>& lines, size_t header, Page& page, Table& table) {
  size_t i = header;
  while (i > 0 && lines[i - 1].rfind("**", 0) != 0) --i;
  if (i == 0) {
    page.errors.push_back(at(table.line) + "a field table under no heading");
    return;
  }
  const std::string& heading = lines[i - 1];
  static const std::regex kRecord(R"(^\*\*(Sensor|Telemetry) log record\*\*, (\d+) bytes)");
  static const std::regex kMessage(R"(\*\*([a-z_]+)\*\* \((0x[0-9A-F]{2})\))");
  std::smatch m;
  if (std::regex_search(heading, m, kRecord)) {
    table.record = std::string(m[1].str() == "Sensor" ? "sensor" : "telemetry") + " log record";
    table.stated_bytes = static_cast<size_t>(std::stoul(m[2].str()));
    return;
  }
  for (std::sregex_iterator it(heading.begin(), heading.end(), kMessage), end; it != end; ++it) {
    const std::string name = (*it)[1].str();
    const MessageRow* row = page.message(name);
    if (row == nullptr) {
      page.errors.push_back(at(static_cast<int>(i)) + "a heading for a message section 3 does not list: " + name);
    } else if (static_cast<unsigned>(std::stoul((*it)[2].str(), nullptr, 16)) != row->type) {
      page.errors.push_back(at(static_cast<int>(i)) + name + "'s type byte differs from section 3's");
    }
    table.messages.push_back(name);
  }
  if (table.messages.empty()) page.errors.push_back(at(table.line) + "a field table whose heading names no message");
}

}  // namespace

std::string Scalar::name() const { return (is_signed ? "i" : "u") + std::to_string(bytes * 8); }

bool Range::states_a_range() const {
  return min || max || !for_message.empty() || bits || !below.empty() || !at_most.empty() || acked_type ||
         nul_padding || counter || parameter_range;
}

std::string Range::describe() const {
  std::string d;
  const auto add = [&](const std::string& s) { d += (d.empty() ? "" : ", ") + s; };
  if (min || max) add((min ? std::to_string(*min) : "") + ".." + (max ? std::to_string(*max) : ""));
  for (const auto& [who, range] : for_message)
    add(std::to_string(range.first) + ".." + std::to_string(range.second) + " (" + who + ")");
  if (bits) {
    char mask[16];
    std::snprintf(mask, sizeof mask, "0x%02X", *bits);
    add(std::string("bits ") + mask);
  }
  if (!below.empty()) add("< " + below);
  if (!at_most.empty()) add("<= " + at_most);
  if (acked_type) add("an acked type");
  if (nul_padding) add("0x00 only as padding");
  if (counter) add("+1 per frame");
  if (parameter_range) add("within the parameter's range");
  if (!same_as.empty()) add("as " + same_as);
  if (sender_only) add("the sender's promise, no decoding rule");
  return d.empty() ? "no range" : d;
}

size_t Table::bytes() const {
  size_t n = 0;
  for (const Field& f : fields) n += f.scalar.bytes * f.count;
  return n;
}

const Field* Table::field(const std::string& name) const {
  for (const Field& f : fields) {
    if (std::find(f.names.begin(), f.names.end(), name) != f.names.end()) return &f;
  }
  return nullptr;
}

const MessageRow* Page::message(const std::string& name) const {
  for (const MessageRow& m : messages) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

const MessageRow* Page::message(uint8_t type) const {
  for (const MessageRow& m : messages) {
    if (m.type == type) return &m;
  }
  return nullptr;
}

const Table* Page::table_of(const std::string& message_name) const {
  for (const Table& t : tables) {
    if (std::find(t.messages.begin(), t.messages.end(), message_name) != t.messages.end()) return &t;
  }
  return nullptr;
}

const Table* Page::record(const std::string& record_name) const {
  for (const Table& t : tables) {
    if (t.record == record_name) return &t;
  }
  return nullptr;
}

const Range& Page::range_of(const Table& table, const Field& field) const {
  // A row with a range of its own keeps it ("0..6 as in mode_change" says where the numbers are
  // explained); one with none takes the named message's row ("as telemetry_attitude").
  if (field.range.same_as.empty() || field.range.states_a_range()) return field.range;
  const Table* other = table_of(field.range.same_as);
  const Field* row = other != nullptr && other != &table ? other->field(field.names[0]) : nullptr;
  return row != nullptr ? range_of(*other, *row) : field.range;
}

Page read_page(const std::string& text) {
  Page page;
  std::vector<std::string> lines;
  {
    std::stringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  static const std::regex kMessageRow(
      R"(^\| (0x[0-9A-F]{2}) \| ([a-z_]+) \| (PC→QR|QR→PC) \| (\d+) \| (yes|no) \| (yes|no) \| (\d+) \|$)");
  static const std::regex kTaskRow(R"(^\| (\d+) \| `[a-z_]+` \|$)");
  for (size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (std::regex_match(lines[i], m, kMessageRow)) {
      page.messages.push_back(MessageRow{static_cast<uint8_t>(std::stoul(m[1].str(), nullptr, 16)), m[2].str(),
                                         m[3].str() == "QR→PC", static_cast<size_t>(std::stoul(m[4].str())),
                                         m[5].str() == "yes"});
    }
    if (lines[i] == "| task | name |") {
      for (size_t j = i + 2; j < lines.size() && std::regex_match(lines[j], m, kTaskRow); ++j) {
        if (std::stoul(m[1].str()) != page.task_rows)
          page.errors.push_back(at(static_cast<int>(j + 1)) + "task rows out of order");
        ++page.task_rows;
      }
    }
  }

  static const std::regex kHeader(R"(^\| offset \| type \| field \| unit( / range)? \|$)");
  static const std::regex kRow(
      R"(^\| (\d+) \| (?:(\d+) × )?([a-z0-9]+) \| ([a-z_][a-z0-9_]*(?:, [a-z_][a-z0-9_]*)*) \| (?:(.*) )?\|$)");
  for (size_t i = 0; i < lines.size(); ++i) {
    if (!std::regex_match(lines[i], kHeader)) continue;
    Table table;
    table.line = static_cast<int>(i + 1);
    read_heading(lines, i, page, table);
    const bool ranges = table.record.empty() ? !table.messages.empty() && page.message(table.messages[0]) != nullptr &&
                                                   page.message(table.messages[0])->qr_to_pc
                                             : true;
    size_t j = i + 2;
    for (; j < lines.size() && lines[j].rfind("|", 0) == 0; ++j) {
      const int line = static_cast<int>(j + 1);
      std::smatch m;
      if (!std::regex_match(lines[j], m, kRow)) {
        page.errors.push_back(at(line) + "a row the reader cannot read: " + lines[j]);
        continue;
      }
      Field f;
      f.line = line;
      f.offset = static_cast<size_t>(std::stoul(m[1].str()));
      f.count = m[2].matched ? static_cast<size_t>(std::stoul(m[2].str())) : 1;
      const std::optional<Scalar> scalar = read_scalar(m[3].str());
      if (!scalar) {
        page.errors.push_back(at(line) + "no such type: " + m[3].str());
        continue;
      }
      f.scalar = *scalar;
      f.names = split_names(m[4].str());
      if (f.names.size() != 1 && f.names.size() != f.count) {
        page.errors.push_back(at(line) + "neither one name nor one per element: " + lines[j]);
      }
      f.cell = m[5].str();
      // Only what the QR sends is judged here; the PC's requests have the QR's decoder.
      if (ranges) f.range = read_range(f.cell, f.names[0], line, page.errors);
      table.fields.push_back(f);
    }
    size_t next = 0;
    for (const Field& f : table.fields) {
      if (f.offset != next)
        page.errors.push_back(at(f.line) + "offset " + std::to_string(f.offset) + ", but the rows above end at " +
                              std::to_string(next));
      next = f.offset + f.scalar.bytes * f.count;
    }
    page.tables.push_back(table);
    i = j;
  }

  // Names a range refers to must be there: a typo would otherwise check nothing.
  for (Table& table : page.tables) {
    for (Field& f : table.fields) {
      Range& r = f.range;
      if (r.below == "N") {  // "0..N−1: the row of the firmware's task table, N rows (below)"
        if (page.task_rows == 0) page.errors.push_back(at(f.line) + "N, but no task table");
        r.max = static_cast<long long>(page.task_rows) - 1;
        r.min = 0;
        r.below.clear();
      }
      if (!r.below.empty() && table.field(r.below) == nullptr)
        page.errors.push_back(at(f.line) + "no field " + r.below);
      if (!r.at_most.empty() && table.field(r.at_most) == nullptr)
        page.errors.push_back(at(f.line) + "no field " + r.at_most);
      for (const auto& entry : r.for_message) {
        const std::string& who = entry.first;
        const auto n = std::count_if(table.messages.begin(), table.messages.end(),
                                     [&](const std::string& name) { return name.rfind(who, 0) == 0; });
        if (n != 1) page.errors.push_back(at(f.line) + "'(" + who + ")' names none or several of the table's messages");
      }
      if (!r.same_as.empty()) {
        if (page.message(r.same_as) == nullptr)
          page.errors.push_back(at(f.line) + "'as " + r.same_as + "': no such message");
        // Nothing of its own, and nothing the named row gives: a range nobody would check.
        else if (!r.states_a_range() && !page.range_of(table, f).states_a_range())
          page.errors.push_back(at(f.line) + "'as " + r.same_as + "', but that message has no row " + f.names[0] +
                                " with a range the reader reads");
      }
    }
  }
  return page;
}

Page read_page_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream all;
  all << in.rdbuf();
  Page page = read_page(all.str());
  if (page.messages.empty()) page.errors.push_back("cannot read " + path);
  return page;
}

std::string Violation::text() const {
  return at(line) + field + " = " + std::to_string(value) + ", but the page says " + says;
}

std::vector<long long> values_of(const Field& field, const uint8_t* bytes, size_t length) {
  std::vector<long long> values;
  for (size_t k = 0; k < field.count; ++k) {
    const size_t from = field.offset + k * field.scalar.bytes;
    if (from + field.scalar.bytes > length) break;
    uint64_t raw = 0;
    for (size_t b = 0; b < field.scalar.bytes; ++b) raw |= static_cast<uint64_t>(bytes[from + b]) << (8 * b);
    const unsigned bits = static_cast<unsigned>(8 * field.scalar.bytes);
    long long v = static_cast<long long>(raw);
    if (field.scalar.is_signed && (raw >> (bits - 1)) != 0) v -= 1LL << bits;
    values.push_back(v);
  }
  return values;
}

std::vector<Violation> check(const Page& page, const Table& table, const std::string& message, const uint8_t* bytes,
                             size_t length, bool decoding_rules_only, ParameterRange parameter_ok) {
  std::vector<Violation> out;
  const std::string prefix = (message.empty() ? table.record : message) + ".";
  const auto first_value = [&](const std::string& name, long long& v) {
    const Field* f = table.field(name);
    if (f == nullptr) return false;
    const std::vector<long long> values = values_of(*f, bytes, length);
    const auto it = std::find(f->names.begin(), f->names.end(), name);
    const size_t index = f->names.size() == f->count ? static_cast<size_t>(it - f->names.begin()) : 0;
    if (index >= values.size()) return false;
    v = values[index];
    return true;
  };
  for (const Field& f : table.fields) {
    const Range& r = page.range_of(table, f);
    if (decoding_rules_only && r.sender_only) continue;
    const std::vector<long long> values = values_of(f, bytes, length);
    bool padding = false;
    for (size_t k = 0; k < values.size(); ++k) {
      const long long v = values[k];
      const auto broken = [&](const std::string& says) {
        const bool array = f.count > 1 && f.names.size() == 1;
        out.push_back(Violation{f.line, prefix + f.name_of(k) + (array ? "[" + std::to_string(k) + "]" : ""), v, says});
      };
      if ((r.min && v < *r.min) || (r.max && v > *r.max)) broken(r.describe());
      if (!r.for_message.empty()) {
        bool known = false;
        for (const auto& [who, range] : r.for_message) {
          if (message.rfind(who, 0) != 0) continue;
          known = true;
          if (v < range.first || v > range.second) broken(r.describe());
        }
        if (!known) broken(r.describe() + ", nothing for " + message);
      }
      if (r.bits && (static_cast<unsigned long long>(v) & ~static_cast<unsigned long long>(*r.bits)) != 0)
        broken(r.describe());
      long long other = 0;
      if (!r.below.empty() && first_value(r.below, other) && !(v < other)) broken(r.describe());
      if (!r.at_most.empty() && first_value(r.at_most, other) && !(v <= other)) broken(r.describe());
      if (r.acked_type) {
        const MessageRow* m = v >= 0 && v <= 255 ? page.message(static_cast<uint8_t>(v)) : nullptr;
        if (m == nullptr || !m->acked) broken(r.describe());
      }
      if (r.parameter_range && parameter_ok != nullptr && first_value("id", other) && !parameter_ok(other, v))
        broken(r.describe());
      if (r.nul_padding) {
        if (v == 0) padding = true;
        else if (padding) broken(r.describe());
      }
    }
  }
  return out;
}

}  // namespace protocol_page
