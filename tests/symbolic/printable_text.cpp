// Text on its way to a terminal or a CSV header: control and bidirectional characters escaped,
// and the rule for names (printable, no formula prefix for a CSV column).
#include "unidyn/symbolic/printable_text.hpp"

#include <gtest/gtest.h>

namespace unidyn {
namespace {

TEST(PrintableText, ControlCharactersAreEscaped) {
  EXPECT_EQ(printable("plain text, θ and é"), "plain text, θ and é");
  EXPECT_EQ(printable("a\nb\tc\rd"), "a\\nb\\tc\\rd");
  EXPECT_EQ(printable("\x1b[31mred\x1b[0m"), "\\e[31mred\\e[0m");
  EXPECT_EQ(printable(std::string("nul\0x", 5)), "nul\\x00x");
  EXPECT_EQ(printable("del\x7f"), "del\\x7F");
  // C1 (U+009B is a one-byte CSI on some terminals) and the bidirectional controls
  EXPECT_EQ(printable("\xc2\x9b"
                      "2J"),
            "\\u{009B}2J");
  EXPECT_EQ(printable("abc\xe2\x80\xae"
                      "def"),
            "abc\\u{202E}def");
  EXPECT_EQ(printable("\xe2\x81\xa6x\xe2\x81\xa9"), "\\u{2066}x\\u{2069}");
  EXPECT_EQ(printable("\xd8\x9c"), "\\u{061C}");
  // bytes that are not UTF-8: stray continuation, overlong, surrogate, truncated
  EXPECT_EQ(printable("\x80"), "\\x80");
  EXPECT_EQ(printable("\xc0\xaf"), "\\xC0\\xAF");
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xED\\xA0\\x80");
  EXPECT_EQ(printable("ab\xe2\x80"), "ab\\xE2\\x80");
  // four-byte characters pass
  EXPECT_EQ(printable("\xf0\x9f\x99\x82"), "\xf0\x9f\x99\x82");
}

TEST(PrintableText, NamesArePrintableText) {
  EXPECT_EQ(unprintable_name_reason("tension", true), "");
  EXPECT_EQ(unprintable_name_reason("H_O·E3 (about O)", true), "");
  EXPECT_NE(unprintable_name_reason("", false), "");
  EXPECT_NE(unprintable_name_reason("a\nb", false).find("\\n"), std::string::npos);
  EXPECT_NE(unprintable_name_reason("\x1b[2J", false).find("\\e"), std::string::npos);
  EXPECT_NE(unprintable_name_reason("x\xe2\x80\xae", false).find("\\u{202E}"), std::string::npos);
  EXPECT_NE(unprintable_name_reason("\xff", false), "");
  // formula prefixes only matter for a CSV column
  for (const char* formula : {"=1+1", "+1", "-x", "@SUM(A1)"}) {
    EXPECT_NE(unprintable_name_reason(formula, true).find("formula"), std::string::npos) << formula;
    EXPECT_EQ(unprintable_name_reason(formula, false), "") << formula;
  }
}

}  // namespace
}  // namespace unidyn
