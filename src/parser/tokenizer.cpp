#include "parser/tokenizer.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace candela {

namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool isDelimiter(char c) { return isSpace(c) || c == '"' || c == '[' || c == ']' || c == '#'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// pbrt's number syntax: [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)?. Stricter
// than strtod, which would also take "inf", "nan" and hexadecimal.
bool isNumberSyntax(std::string_view s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t mantissaDigits = 0;
  while (i < s.size() && isDigit(s[i])) ++i, ++mantissaDigits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && isDigit(s[i])) ++i, ++mantissaDigits;
  }
  if (mantissaDigits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t expDigits = 0;
    while (i < s.size() && isDigit(s[i])) ++i, ++expDigits;
    if (expDigits == 0) return false;
  }
  return i == s.size();
}

}  // namespace

std::string printable(std::string_view text, size_t maxLength) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (i == maxLength) {
      out += "...";
      break;
    }
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

std::string describeToken(const Token& t) {
  // Appending (rather than "'" + s + "'") avoids a GCC 12 -Wrestrict false positive.
  auto wrap = [&](const char* open, const char* close) {
    std::string s = open;
    s += printable(t.text);
    s += close;
    return s;
  };
  switch (t.kind) {
    case TokenKind::String:
      return wrap("string \"", "\"");
    case TokenKind::Number:
      return wrap("number ", "");
    case TokenKind::Word:
      return wrap("'", "'");
    case TokenKind::OpenBracket:
      return "'['";
    case TokenKind::CloseBracket:
      return "']'";
    case TokenKind::End:
      return "end of file";
  }
  return "token";
}

Tokenizer::Tokenizer(std::string text, std::string filename)
    : text_(std::move(text)), filename_(std::move(filename)) {}

char Tokenizer::get() {
  char c = text_[pos_++];
  if (c == '\n') {
    ++line_;
    column_ = 1;
  } else {
    ++column_;
  }
  return c;
}

void Tokenizer::skipSpaceAndComments() {
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (isSpace(c)) {
      get();
    } else if (c == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') get();
    } else {
      break;
    }
  }
}

const Token& Tokenizer::peek() {
  if (!havePeeked_) {
    peeked_ = scan();
    havePeeked_ = true;
  }
  return peeked_;
}

Token Tokenizer::next() {
  if (havePeeked_) {
    havePeeked_ = false;
    return std::move(peeked_);
  }
  return scan();
}

Token Tokenizer::scan() {
  skipSpaceAndComments();
  Token tok;
  tok.loc = here();
  if (pos_ >= text_.size()) return tok;  // End

  char c = text_[pos_];
  if (c == '[' || c == ']') {
    get();
    tok.kind = c == '[' ? TokenKind::OpenBracket : TokenKind::CloseBracket;
    tok.text = std::string(1, c);
    return tok;
  }

  if (c == '"') {
    // A string ends at the next unescaped quote on the same line (pbrt-v2's lexer does not let a
    // string span lines, so a missing quote is caught where it happened).
    get();
    tok.kind = TokenKind::String;
    while (true) {
      if (pos_ >= text_.size() || text_[pos_] == '\n')
        throw SceneError(tok.loc, "unterminated string: missing closing '\"'");
      char ch = get();
      if (ch == '"') break;
      if (ch == '\\' && pos_ < text_.size() && text_[pos_] != '\n') {
        char e = get();
        switch (e) {
          case 'n':
            tok.text += '\n';
            break;
          case 't':
            tok.text += '\t';
            break;
          case 'r':
            tok.text += '\r';
            break;
          case 'b':
            tok.text += '\b';
            break;
          case 'f':
            tok.text += '\f';
            break;
          case '"':
          case '\\':
            tok.text += e;
            break;
          default:  // not an escape (pbrt-v2 has none): keep "C:\dir" as written
            tok.text += '\\';
            tok.text += e;
        }
        continue;
      }
      tok.text += ch;
    }
    return tok;
  }

  size_t start = pos_;
  while (pos_ < text_.size() && !isDelimiter(text_[pos_])) get();
  tok.text = text_.substr(start, pos_ - start);
  if (isDigit(c) || c == '-' || c == '+' || c == '.') {
    if (!isNumberSyntax(tok.text))
      throw SceneError(tok.loc, "malformed number '" + printable(tok.text) + "'");
    const char* first = tok.text.data() + (c == '+' ? 1 : 0);
    auto [ptr, ec] = std::from_chars(first, tok.text.data() + tok.text.size(), tok.number);
    if (ec == std::errc::result_out_of_range || !std::isfinite(tok.number) ||
        std::abs(tok.number) > std::numeric_limits<float>::max())
      throw SceneError(tok.loc, "number '" + printable(tok.text) + "' is out of range");
    if (ec != std::errc() || ptr != tok.text.data() + tok.text.size())
      throw SceneError(tok.loc, "malformed number '" + printable(tok.text) + "'");
    tok.kind = TokenKind::Number;
  } else {
    tok.kind = TokenKind::Word;
  }
  return tok;
}

}  // namespace candela
