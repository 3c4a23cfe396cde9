// Where each function of a C++ source begins and ends, read from the text alone (no compiler): the
// check that keeps functions short (Layering.NoFunctionOver80Lines) counts lines with it.
//
// It knows just enough C++ for this project's layout: comments, string and character literals and
// preprocessor lines are blanked first; then a brace at namespace or class scope opens a function
// body when the text before it since the last `;`, `{` or `}` has a parameter list and no `=`.
// A constructor's member initialisers in braces (`x_{1}`) are not its body. Lambdas, local classes
// and blocks inside a function count as the function's lines; a lambda assigned at namespace
// scope (`const auto f = [] { ... };`) is an initialiser, not counted.
#pragma once

#include <stddef.h>

#include <string>
#include <vector>

namespace qrterm_test {

struct FunctionSpan {
  std::string name;       // as written before its parameter list: "Console::act", "operator()"
  size_t first_line = 0;  // 1-based: where its declaration starts (a template line included)
  size_t last_line = 0;   // its closing brace
  size_t lines() const { return last_line - first_line + 1; }
};

std::vector<FunctionSpan> function_spans(const std::string& source);

// The source with comments, literals and preprocessor lines turned to spaces, newlines kept.
std::string blank_non_code(const std::string& source);

}  // namespace qrterm_test
