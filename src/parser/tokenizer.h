// Splits scene-file text into tokens (lrt draft App. C: keywords, quoted strings, numbers, [ ],
// '#' comments), remembering file:line:col of each so every error can point at its cause.
#pragma once

#include <string>
#include <string_view>

#include "core/error.h"

namespace candela {

enum class TokenKind {
  String,        // "..." (text holds the contents with escapes resolved)
  Number,        // text as written, number holds its value
  Word,          // a bare word: a directive, ActiveTransform's argument, true/false
  OpenBracket,   // [
  CloseBracket,  // ]
  End            // end of the text
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;
  double number = 0;
  FileLoc loc;
};

// "string \"a b\"", "number 1.5", "word Shape", "'['", "end of file": for error messages. Long or
// binary text is shortened and escaped.
std::string describeToken(const Token& t);
// Printable text for a message: control and non-ASCII bytes as \xNN, cut after maxLength.
std::string printable(std::string_view text, size_t maxLength = 40);

class Tokenizer {
 public:
  // The text is copied; filename is used only in locations.
  Tokenizer(std::string text, std::string filename);

  // The next token; End forever after the last. Throws SceneError for an unterminated string or
  // a malformed or out-of-range number, at the token's first character.
  Token next();
  const Token& peek();
  const std::string& filename() const { return filename_; }

 private:
  Token scan();
  void skipSpaceAndComments();
  char get();  // consumes one character, tracking line and column
  FileLoc here() const { return {filename_, line_, column_}; }

  std::string text_, filename_;
  size_t pos_ = 0;
  int line_ = 1, column_ = 1;
  Token peeked_;
  bool havePeeked_ = false;
};

}  // namespace candela
