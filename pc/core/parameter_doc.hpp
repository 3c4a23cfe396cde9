// docs/parameters.md, made from the shared parameter table (common/parameter_table.hpp): one row
// per parameter with its id, unit, Q format, range and default as raw integers and as real values.
// The document is never edited by hand; qrparams --markdown writes it and a test compares.
#pragma once

#include <string>

namespace qrterm {

// The whole document, ending in a newline.
std::string parameters_markdown();

// Where text and expected first differ, as "line N: expected \"...\", found \"...\"", or an
// empty string when they are the same.
std::string first_difference(const std::string& expected, const std::string& text);

}  // namespace qrterm
