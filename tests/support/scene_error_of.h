// What a SceneError says: the tests of located errors compare whole messages
// ("t.pbrt:2:3: error: ..."), so they need the text of the error a call throws.
#pragma once

#include <string>

#include "core/error.h"

namespace candela::test {

// The message of the SceneError f() throws, or "(no error)" when it throws none (so that an
// expectation on the text fails, naming that nothing was thrown).
template <typename F>
std::string sceneErrorOf(F&& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace candela::test
