#include "function_spans.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace qrterm_test {
namespace {

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Blanks from `at` through the end of a preprocessor line, its continuations included.
size_t blank_directive(std::string& out, size_t at) {
  while (at < out.size() && out[at] != '\n') {
    if (out[at] == '\\' && at + 1 < out.size() && out[at + 1] == '\n') {
      out[at] = ' ';
      at += 2;
      continue;
    }
    out[at++] = ' ';
  }
  return at;
}

// Blanks a quoted literal that starts at `at` (its quote), escapes honoured; returns where it ends.
size_t blank_quoted(std::string& out, size_t at, char quote) {
  out[at++] = ' ';
  while (at < out.size() && out[at] != quote && out[at] != '\n') {
    if (out[at] == '\\' && at + 1 < out.size()) out[at++] = ' ';
    out[at++] = ' ';
  }
  if (at < out.size() && out[at] == quote) out[at++] = ' ';
  return at;
}

// R"delim( ... )delim": `at` is the quote.
size_t blank_raw(std::string& out, size_t at) {
  const size_t open = out.find('(', at);
  if (open == std::string::npos) return blank_quoted(out, at, '"');
  const std::string close = ")" + out.substr(at + 1, open - at - 1) + "\"";
  size_t end = out.find(close, open);
  end = end == std::string::npos ? out.size() : end + close.size();
  for (size_t i = at; i < end; ++i) {
    if (out[i] != '\n') out[i] = ' ';
  }
  return end;
}

}  // namespace

std::string blank_non_code(const std::string& source) {
  std::string out = source;
  bool line_start = true;  // only spaces so far on this line
  size_t i = 0;
  while (i < out.size()) {
    const char c = out[i];
    const char next = i + 1 < out.size() ? out[i + 1] : '\0';
    if (c == '\n') {
      line_start = true;
      ++i;
    } else if (c == '#' && line_start) {
      i = blank_directive(out, i);
    } else if (c == '/' && next == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (c == '/' && next == '*') {
      while (i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/')) {
        if (out[i] != '\n') out[i] = ' ';
        ++i;
      }
      if (i < out.size()) out[i++] = ' ';
      if (i < out.size()) out[i++] = ' ';
    } else if (c == '"' && i > 0 && out[i - 1] == 'R' && (i < 2 || !identifier_char(out[i - 2]) || out[i - 2] == '8')) {
      line_start = false;
      i = blank_raw(out, i);
    } else if (c == '"') {
      line_start = false;
      i = blank_quoted(out, i, '"');
    } else if (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(out[i - 1])) != 0 &&
                              std::isxdigit(static_cast<unsigned char>(next)) != 0)) {
      line_start = false;  // a character literal, not a digit separator (1'000)
      i = blank_quoted(out, i, '\'');
    } else {
      if (c != ' ' && c != '\t' && c != '\r') line_start = false;
      ++i;
    }
  }
  return out;
}

namespace {

enum class HeadKind { namespace_scope, class_scope, skip, member_initialiser, function };

struct Head {
  HeadKind kind = HeadKind::skip;
  std::string name;
};

std::string trim(const std::string& text) {
  const size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  const size_t end = text.find_last_not_of(" \t\r\n");
  return text.substr(begin, end - begin + 1);
}

bool starts_with_word(const std::string& text, const char* word) {
  const size_t n = std::strlen(word);
  return text.compare(0, n, word) == 0 && (text.size() == n || !identifier_char(text[n]));
}

// Drops leading `template <...>` and `[[...]]`: they say nothing about what the brace opens.
std::string strip_prefixes(std::string head) {
  for (;;) {
    head = trim(head);
    if (starts_with_word(head, "template")) {
      const size_t open = head.find('<');
      if (open == std::string::npos) return head;
      int depth = 0;
      size_t at = open;
      for (; at < head.size(); ++at) {
        if (head[at] == '<') ++depth;
        if (head[at] == '>' && --depth == 0) break;
      }
      head = head.substr(std::min(at + 1, head.size()));
    } else if (head.rfind("[[", 0) == 0) {
      const size_t close = head.find("]]");
      if (close == std::string::npos) return head;
      head = head.substr(close + 2);
    } else {
      return head;
    }
  }
}

// After `operator` at `at`: past the operator's symbol (`()`, `[]`, `==`, `<<`, or a type name).
size_t skip_operator_symbol(const std::string& head, size_t at) {
  while (at < head.size() && head[at] == ' ') ++at;
  if (head.compare(at, 2, "()") == 0 || head.compare(at, 2, "[]") == 0) return at + 2;
  const size_t symbols = head.find_first_not_of("+-*/%^&|~!=<>,", at);
  if (symbols != at) return symbols == std::string::npos ? head.size() : symbols;
  while (at < head.size() && (identifier_char(head[at]) || head[at] == ':' || head[at] == ' ')) ++at;
  return at;
}

// The name just before `end`: "Console::act", "~Console", "operator()".
std::string name_before(const std::string& head, size_t end) {
  size_t begin = end;
  while (begin > 0 && (identifier_char(head[begin - 1]) || head[begin - 1] == ':' || head[begin - 1] == '~')) --begin;
  const size_t op = head.rfind("operator", end);
  if (op != std::string::npos && op < end && (op == 0 || !identifier_char(head[op - 1]))) begin = std::min(begin, op);
  return trim(head.substr(begin, end - begin));
}

Head classify(const std::string& raw_head) {
  const std::string head = strip_prefixes(raw_head);
  if (starts_with_word(head, "namespace") ||
      (starts_with_word(head, "inline") && head.find("namespace") != std::string::npos) ||
      (starts_with_word(head, "extern") && head.find('(') == std::string::npos)) {
    return {HeadKind::namespace_scope, ""};
  }
  if (starts_with_word(head, "class") || starts_with_word(head, "struct") || starts_with_word(head, "union")) {
    return {HeadKind::class_scope, ""};
  }
  if (starts_with_word(head, "enum") || head.empty()) return {HeadKind::skip, ""};

  int parens = 0, angles = 0;
  size_t params = std::string::npos;  // the first `(` outside any nesting: the parameter list
  bool assigned = false;              // an `=` before it: an initialiser
  bool closed_params = false, initialisers = false;
  for (size_t i = 0; i < head.size(); ++i) {
    const char c = head[i];
    if (head.compare(i, 8, "operator") == 0 && (i == 0 || !identifier_char(head[i - 1])) &&
        (i + 8 == head.size() || !identifier_char(head[i + 8]))) {
      i = skip_operator_symbol(head, i + 8) - 1;
      continue;
    }
    if (c == '(') {
      if (parens == 0 && angles == 0 && params == std::string::npos) params = i;
      ++parens;
    } else if (c == ')') {
      if (--parens == 0 && angles == 0) closed_params = true;
    } else if (parens > 0) {
      continue;
    } else if (c == '<' && i > 0 && (identifier_char(head[i - 1]) || head[i - 1] == ' ')) {
      ++angles;
    } else if (c == '>' && angles > 0 && head[i - 1] != '-') {
      --angles;
    } else if (c == '=' && angles == 0 && params == std::string::npos) {
      assigned = true;
    } else if (c == ':' && angles == 0 && closed_params) {
      const bool scope = (i + 1 < head.size() && head[i + 1] == ':') || head[i - 1] == ':';
      if (!scope) initialisers = true;
    }
  }
  // Unclosed parentheses: the brace is inside an expression (a lambda passed to an initialiser).
  if (params == std::string::npos || assigned || parens != 0) return {HeadKind::skip, ""};
  if (initialisers) {
    // In a constructor's member initialisers, `x_{1}` is one of them; the body follows `)` or `}`.
    const char last = trim(head).back();
    if (identifier_char(last) || last == '>') return {HeadKind::member_initialiser, ""};
  }
  return {HeadKind::function, name_before(head, params)};
}

size_t matching_brace(const std::string& code, size_t open) {
  int depth = 0;
  for (size_t i = open; i < code.size(); ++i) {
    if (code[i] == '{') ++depth;
    if (code[i] == '}' && --depth == 0) return i;
  }
  return code.size() - 1;
}

}  // namespace

std::vector<FunctionSpan> function_spans(const std::string& source) {
  const std::string code = blank_non_code(source);
  std::vector<size_t> line_starts{0};
  for (size_t i = 0; i < code.size(); ++i) {
    if (code[i] == '\n') line_starts.push_back(i + 1);
  }
  const auto line_of = [&](size_t at) {
    return static_cast<size_t>(std::upper_bound(line_starts.begin(), line_starts.end(), at) - line_starts.begin());
  };

  std::vector<FunctionSpan> spans;
  std::vector<HeadKind> scopes;  // namespace or class scopes open around the current point
  std::string head;              // the text since the last `;`, `{` or `}` at this scope
  size_t head_start = 0;         // its first character that is not a space
  bool head_started = false;
  const auto reset = [&] {
    head.clear();
    head_started = false;
  };
  for (size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (c == ';') {
      reset();
    } else if (c == '}') {
      if (!scopes.empty()) scopes.pop_back();
      reset();
    } else if (c == ':' && !scopes.empty() && scopes.back() == HeadKind::class_scope &&
               (trim(head) == "public" || trim(head) == "private" || trim(head) == "protected")) {
      reset();
    } else if (c == '{') {
      const Head what = classify(head);
      if (what.kind == HeadKind::namespace_scope || what.kind == HeadKind::class_scope) {
        scopes.push_back(what.kind);
        reset();
      } else if (what.kind == HeadKind::member_initialiser) {
        i = matching_brace(code, i);
        head += "{}";
      } else if (what.kind == HeadKind::function) {
        const size_t close = matching_brace(code, i);
        spans.push_back({what.name, line_of(head_start), line_of(close)});
        i = close;
        reset();
      } else {
        i = matching_brace(code, i);
        head += "{}";
      }
    } else {
      if (!head_started && c != ' ' && c != '\n' && c != '\t' && c != '\r') {
        head_start = i;
        head_started = true;
      }
      head += c;
    }
  }
  return spans;
}

}  // namespace qrterm_test
