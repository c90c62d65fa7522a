// Text from a model file or the command line on its way to a terminal or a CSV header: control
// characters (which could move the cursor, recolour or clear the screen, or split a line) and
// bidirectional controls (which reorder what is shown, as U+202E does) are never passed on raw.
#pragma once

#include <string>
#include <string_view>

namespace unidyn {

// The text with every control character escaped: C0 controls (newline and tab included) and DEL
// as \n, \t, \r, \e or \xNN; C1 controls and the bidirectional controls (U+061C, U+200E, U+200F,
// U+202A–U+202E, U+2066–U+2069) as \u{XXXX}; bytes that are not UTF-8 as \xNN; a backslash as is.
std::string printable(std::string_view text);

// Why `text` cannot be a name (of a model, an output, a CSV column), or "" when it can: it is
// empty, is not UTF-8, or holds a control character; a name that becomes a CSV column also must
// not start with = + - @ (a spreadsheet would take it for a formula).
std::string unprintable_name_reason(std::string_view text, bool csv_column);

}  // namespace unidyn
