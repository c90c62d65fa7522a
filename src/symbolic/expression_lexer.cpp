// Lexer of the model-file expression language: tokens, positions and exact numbers.
#include "expression_lexer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <utility>

#include "unidyn/symbolic/expression_parser.hpp"

namespace unidyn::detail {
namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_name_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_name_char(char c) {
  return is_name_start(c) || is_digit(c);
}
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
// The second, third or fourth byte of a UTF-8 character: not a column of its own.
bool is_continuation(char c) {
  return (static_cast<unsigned char>(c) & 0xC0u) == 0x80u;
}

// a + b clamped to the range of int (positions of absurd origins must not overflow).
int clamped_sum(int a, int b) {
  const long long sum = static_cast<long long>(a) + b;
  return static_cast<int>(
      std::clamp<long long>(sum, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

// A character for a message: itself if printable ASCII, else its byte value.
std::string character_name(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x21 && byte <= 0x7E) return "'" + std::string(1, c) + "'";
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "(byte 0x%02X)", static_cast<unsigned>(byte));
  return buffer;
}

// Decimal digits an exact number may have.
int max_digits() {
  return static_cast<int>(ExpressionLimits::max_number_bits / std::log2(10.0));
}

// The integer a string of decimal digits stands for, nine digits at a time.
GiNaC::numeric integer_from_digits(std::string_view digits) {
  GiNaC::numeric value = 0;
  for (std::size_t at = 0; at < digits.size(); at += 9) {
    const std::string_view chunk = digits.substr(at, 9);
    long part = 0;
    for (char c : chunk) part = part * 10 + (c - '0');
    value =
        value * GiNaC::numeric(10).power(static_cast<long>(chunk.size())) + GiNaC::numeric(part);
  }
  return value;
}

}  // namespace

Lexer::Lexer(std::string_view text, SourcePosition origin)
    : text_(text), origin_(std::move(origin)) {}

// Look ahead without consuming; '\0' past the end (a real NUL byte is no token either).
char Lexer::peek(std::size_t ahead) const {
  return at_ + ahead < text_.size() ? text_[at_ + ahead] : '\0';
}

// Consume characters, counting lines and columns.
void Lexer::advance(std::size_t count) {
  for (; count > 0 && at_ < text_.size(); --count, ++at_) {
    if (text_[at_] == '\n') {
      ++line_;
      column_ = 0;
    } else if (!is_continuation(text_[at_])) {
      ++column_;
    }
  }
}

void Lexer::skip_whitespace() {
  while (at_ < text_.size() && is_space(text_[at_])) advance();
}

SourcePosition Lexer::position() const {
  // Text without a known origin: positions within the text.
  if (origin_.line <= 0) return {origin_.file, clamped_sum(line_, 1), clamped_sum(column_, 1)};
  const int first_column = line_ == 0 ? std::max(origin_.column, 1) : 1;
  return {origin_.file, clamped_sum(origin_.line, line_), clamped_sum(first_column, column_)};
}

Token Lexer::make(TokenKind kind, std::size_t start, const SourcePosition& where) const {
  return {kind, text_.substr(start, at_ - start), where};
}

Token Lexer::next() {
  skip_whitespace();
  if (at_ >= text_.size()) return {TokenKind::end, {}, position()};
  const char c = peek();
  if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return lex_number();
  if (is_name_start(c)) return lex_name();
  return lex_symbol();
}

// digits ['.' digits] [('e' | 'E') ['+' | '-'] digits], or '.' digits [...]
Token Lexer::lex_number() {
  const std::size_t start = at_;
  const SourcePosition where = position();
  while (is_digit(peek())) advance();
  if (peek() == '.') {
    advance();
    while (is_digit(peek())) advance();
  }
  if (peek() == 'e' || peek() == 'E') {
    const std::size_t digits_at = peek(1) == '+' || peek(1) == '-' ? 2 : 1;
    if (!is_digit(peek(digits_at))) {
      throw ModelError(where, "malformed number " +
                                  quoted(text_.substr(start, at_ - start + digits_at)) +
                                  ": an exponent needs digits, as in 1e-3");
    }
    advance(digits_at);
    while (is_digit(peek())) advance();
  }
  return make(TokenKind::number, start, where);
}

// identifier ('.' identifier)*, with no spaces around the dots
Token Lexer::lex_name() {
  const std::size_t start = at_;
  const SourcePosition where = position();
  while (is_name_char(peek())) advance();
  while (peek() == '.' && is_name_start(peek(1))) {
    advance();
    while (is_name_char(peek())) advance();
  }
  return make(TokenKind::name, start, where);
}

// One-character operators and punctuation; anything else is an error.
Token Lexer::lex_symbol() {
  const std::size_t start = at_;
  const SourcePosition where = position();
  const char c = peek();
  TokenKind kind = TokenKind::end;
  switch (c) {
    case '+':
      kind = TokenKind::plus;
      break;
    case '-':
      kind = TokenKind::minus;
      break;
    case '*':
      kind = TokenKind::star;
      break;
    case '/':
      kind = TokenKind::slash;
      break;
    case '^':
      kind = TokenKind::caret;
      break;
    case '(':
      kind = TokenKind::left_paren;
      break;
    case ')':
      kind = TokenKind::right_paren;
      break;
    case '[':
      kind = TokenKind::left_bracket;
      break;
    case ']':
      kind = TokenKind::right_bracket;
      break;
    case ',':
      kind = TokenKind::comma;
      break;
    default: {
      const bool ascii = static_cast<unsigned char>(c) < 0x80;
      throw ModelError(where, "unexpected character " + character_name(c) +
                                  (ascii ? "" : ": names and operators are ASCII"));
    }
  }
  if (c == '*' && peek(1) == '*') {
    throw ModelError(where, "'**' is not an operator: write ^ for a power");
  }
  advance();
  return make(kind, start, where);
}

std::string quoted(std::string_view text) {
  constexpr std::size_t kShown = 40;
  if (text.size() <= kShown) return "'" + std::string(text) + "'";
  return "'" + std::string(text.substr(0, kShown)) + "...'";
}

std::string describe(const Token& token) {
  return token.kind == TokenKind::end ? "the end of the expression" : quoted(token.text);
}

Expr exact_number(std::string_view text, const SourcePosition& where) {
  // Split into mantissa digits, the count of digits after the point, and the exponent.
  std::string digits;
  long long fraction = 0;
  std::size_t i = 0;
  for (; i < text.size() && is_digit(text[i]); ++i) digits += text[i];
  if (i < text.size() && text[i] == '.') {
    for (++i; i < text.size() && is_digit(text[i]); ++i, ++fraction) digits += text[i];
  }
  long long exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    const bool negative = i < text.size() && text[i] == '-';
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    while (i + 1 < text.size() && text[i] == '0') ++i;
    const std::string_view exponent_digits = text.substr(i);
    if (exponent_digits.size() > 9) {
      throw ModelError(where,
                       "number " + quoted(text) + " out of range: its exponent is too large");
    }
    for (char c : exponent_digits) exponent = exponent * 10 + (c - '0');
    if (negative) exponent = -exponent;
  }

  // Leading zeros carry nothing; zero is zero whatever its exponent.
  const std::size_t first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 0;
  const std::string_view significant = std::string_view(digits).substr(first);

  // value = significant × 10^scale, refused before it is built if it would be too long.
  const long long scale = exponent - fraction;
  const double length =
      static_cast<double>(significant.size()) + std::abs(static_cast<double>(scale));
  if (length > max_digits()) {
    throw ModelError(where, "number " + quoted(text) +
                                " out of range: exact numbers have at most " +
                                std::to_string(max_digits()) + " digits");
  }
  const GiNaC::numeric mantissa = integer_from_digits(significant);
  const GiNaC::numeric power = GiNaC::numeric(10).power(static_cast<long>(std::llabs(scale)));
  return scale >= 0 ? mantissa * power : mantissa / power;
}

}  // namespace unidyn::detail
