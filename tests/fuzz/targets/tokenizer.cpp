#include <cmath>
#include <string>

#include "fuzz/targets/fuzz_targets.h"
#include "parser/tokenizer.h"

namespace candela::fuzz {

// Every token has a location inside the text and a finite number; the tokenizer reaches End in at
// most one token per byte, and stays there.
void tokenizer(std::string_view input) {
  Tokenizer tok(std::string(input), "fuzz.pbrt");
  try {
    for (size_t count = 0;; ++count) {
      if (count > input.size() + 1) broken("the tokenizer does not advance");
      if (count % 2) tok.peek();
      Token t = tok.next();
      if (t.loc.line < 1 || t.loc.column < 1) broken("a token without a location");
      if (t.kind == TokenKind::Number && !std::isfinite(t.number)) broken("a non-finite number");
      if (describeToken(t).empty()) broken("a token without a description");
      if (t.kind == TokenKind::End) {
        if (tok.next().kind != TokenKind::End) broken("a token after End");
        return;
      }
    }
  } catch (const SceneError& e) {
    if (e.location().line < 1) broken("an error without a line");
  }
}

}  // namespace candela::fuzz
