// Test helper: the scenes of tests/robustness/scenes (which tools/robustness-report renders with
// the candela command too), read as text, and edits to them that must apply.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace candela::test {

inline std::string robustnessScene(const std::string& name) {
  std::string path = std::string(CANDELA_SOURCE_DIR) + "/tests/robustness/scenes/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Replaces the first `from` in *text by `to`; throws when there is none (the scene changed).
inline void replaceOnce(std::string* text, const std::string& from, const std::string& to) {
  size_t at = text->find(from);
  if (at == std::string::npos) throw std::logic_error("the scene has no '" + from + "'");
  text->replace(at, from.size(), to);
}

}  // namespace candela::test
