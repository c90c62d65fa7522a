// Tokens of the model-file expression language, with their positions in the model file.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn::detail {

enum class TokenKind {
  end,
  number,
  name,
  plus,
  minus,
  star,
  slash,
  caret,
  left_paren,
  right_paren,
  left_bracket,
  right_bracket,
  comma,
};

struct Token {
  TokenKind kind = TokenKind::end;
  std::string_view text;  // its characters; empty at the end
  SourcePosition where;   // its first character (at the end: just past the last character)
};

// Splits text into tokens, tracking line and column across newlines.
class Lexer {
 public:
  Lexer(std::string_view text, SourcePosition origin);

  // The next token; throws ModelError at a character no token starts with or a malformed number.
  Token next();
  // Where the lexer is: the position of the next character.
  SourcePosition position() const;

 private:
  char peek(std::size_t ahead = 0) const;
  void advance(std::size_t count = 1);
  void skip_whitespace();
  Token make(TokenKind kind, std::size_t start, const SourcePosition& where) const;
  Token lex_number();
  Token lex_name();
  Token lex_symbol();

  std::string_view text_;
  SourcePosition origin_;
  std::size_t at_ = 0;
  int line_ = 0;    // lines since the origin
  int column_ = 0;  // code points since the start of the line
};

// "'x'" for a token, "the end of the expression" at the end; long texts are shortened.
std::string describe(const Token& token);
// Text in quotes, shortened to a readable length.
std::string quoted(std::string_view text);

// A number token as an exact rational: digits × 10^(exponent − fraction digits). Throws
// ModelError at `where` if it would exceed ExpressionLimits::max_number_bits.
Expr exact_number(std::string_view text, const SourcePosition& where);

}  // namespace unidyn::detail
