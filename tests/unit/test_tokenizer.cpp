#include <gtest/gtest.h>

#include <vector>

#include "parser/tokenizer.h"
#include "support/scene_error_of.h"

using namespace candela;

namespace {

std::vector<Token> tokenize(const std::string& text) {
  Tokenizer tok(text, "t.pbrt");
  std::vector<Token> out;
  while (true) {
    Token t = tok.next();
    if (t.kind == TokenKind::End) break;
    out.push_back(t);
  }
  return out;
}

std::string errorOf(const std::string& text) {
  return test::sceneErrorOf([&] { tokenize(text); });
}

}  // namespace

TEST(Tokenizer, KindsTextAndLocations) {
  std::vector<Token> t = tokenize("Shape \"sphere\"\n  \"float radius\" [ 2.5 ]");
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t[0].kind, TokenKind::Word);
  EXPECT_EQ(t[0].text, "Shape");
  EXPECT_EQ(t[0].loc.str(), "t.pbrt:1:1");
  EXPECT_EQ(t[1].kind, TokenKind::String);
  EXPECT_EQ(t[1].text, "sphere");
  EXPECT_EQ(t[1].loc.str(), "t.pbrt:1:7");
  EXPECT_EQ(t[2].text, "float radius");
  EXPECT_EQ(t[2].loc.str(), "t.pbrt:2:3");
  EXPECT_EQ(t[3].kind, TokenKind::OpenBracket);
  EXPECT_EQ(t[3].loc.str(), "t.pbrt:2:18");
  EXPECT_EQ(t[4].kind, TokenKind::Number);
  EXPECT_DOUBLE_EQ(t[4].number, 2.5);
  EXPECT_EQ(t[4].loc.str(), "t.pbrt:2:20");
  EXPECT_EQ(t[5].kind, TokenKind::CloseBracket);
}

TEST(Tokenizer, NumberForms) {
  std::vector<Token> t = tokenize("1 -.25 +3 1e-5 5E-05 2. 0.5e+2 -7");
  std::vector<double> expected = {1, -.25, 3, 1e-5, 5e-5, 2, 50, -7};
  ASSERT_EQ(t.size(), expected.size());
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_EQ(t[i].kind, TokenKind::Number) << t[i].text;
    EXPECT_DOUBLE_EQ(t[i].number, expected[i]) << t[i].text;
  }
}

TEST(Tokenizer, CommentsRunToEndOfLine) {
  // As in ss-envmap.pbrt: a comment straight after a closing bracket.
  std::vector<Token> t =
      tokenize("# header\n\"string mapname\" [\"a.exr\"]#b.exr\"]\nWorldEnd # done");
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[2].text, "a.exr");
  EXPECT_EQ(t[3].kind, TokenKind::CloseBracket);
  EXPECT_EQ(t[4].text, "WorldEnd");
  EXPECT_EQ(t[4].loc.str(), "t.pbrt:3:1");
}

TEST(Tokenizer, StringEscapes) {
  std::vector<Token> t = tokenize(R"("a\"b" "c\\d" "e\nf" "g\th" "C:\dir")");
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[0].text, "a\"b");
  EXPECT_EQ(t[1].text, "c\\d");
  EXPECT_EQ(t[2].text, "e\nf");
  EXPECT_EQ(t[3].text, "g\th");
  EXPECT_EQ(t[4].text, "C:\\dir");  // not an escape: kept as written
}

TEST(Tokenizer, NanAndInfAreWordsNotNumbers) {
  std::vector<Token> t = tokenize("nan inf true");
  ASSERT_EQ(t.size(), 3u);
  for (const Token& x : t) EXPECT_EQ(x.kind, TokenKind::Word);
}

TEST(Tokenizer, PeekDoesNotConsume) {
  Tokenizer tok("A B", "t.pbrt");
  EXPECT_EQ(tok.peek().text, "A");
  EXPECT_EQ(tok.next().text, "A");
  EXPECT_EQ(tok.next().text, "B");
  Token end = tok.next();
  EXPECT_EQ(end.kind, TokenKind::End);
  EXPECT_EQ(end.loc.str(), "t.pbrt:1:4");
  EXPECT_EQ(tok.next().kind, TokenKind::End);
}

TEST(Tokenizer, UnterminatedStringErrorsAtItsStart) {
  EXPECT_EQ(errorOf("Shape\n   \"sphere"),
            "t.pbrt:2:4: error: unterminated string: missing closing '\"'");
  // A string may not run over a line end.
  EXPECT_EQ(errorOf("\"abc\n\"x\""),
            "t.pbrt:1:1: error: unterminated string: missing closing '\"'");
}

TEST(Tokenizer, MalformedNumberErrorsAtIt) {
  EXPECT_EQ(errorOf("Translate 1 1.2.3 4"), "t.pbrt:1:13: error: malformed number '1.2.3'");
  EXPECT_EQ(errorOf("  -nan"), "t.pbrt:1:3: error: malformed number '-nan'");
}

TEST(Tokenizer, OutOfRangeNumberErrorsAtIt) {
  EXPECT_EQ(errorOf("Scale 1e999 1 1"), "t.pbrt:1:7: error: number '1e999' is out of range");
  EXPECT_EQ(errorOf("\n 1e39"), "t.pbrt:2:2: error: number '1e39' is out of range");
}

TEST(Tokenizer, BinaryBytesArePrintedEscaped) {
  std::vector<Token> t = tokenize(std::string("ab\x01\xff", 4));
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(describeToken(t[0]), "'ab\\x01\\xff'");
  EXPECT_EQ(printable(std::string(100, 'x'), 5), "xxxxx...");
}
