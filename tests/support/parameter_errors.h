// Scene-parameter errors are located: a scene whose one plug-in statement carries `parameter`
// alone on line 3, and the check that each bad value is a SceneError there naming the parameter.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "core/error.h"
#include "support/render_scene.h"

namespace candela::test {

// A 4 x 4 film, then `statement` (e.g. `Integrator "sppm"`) with `parameter` on line 3, and a
// point light and a sphere to render.
inline std::string parameterScene(const std::string& statement, const std::string& parameter) {
  return "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n" + statement +
         "\n  " + parameter +
         "\n"
         "WorldBegin\n"
         "LightSource \"point\" \"point from\" [0 0 -1]\n"
         "Shape \"sphere\" \"float radius\" [0.5]\n"
         "WorldEnd\n";
}

// Each item of `bad` (`"integer chains" [0]`) must be a SceneError on line 3 naming "chains".
inline void expectParameterErrorsLocated(const std::string& statement,
                                         std::initializer_list<const char*> bad) {
  for (const char* b : bad) {
    SCOPED_TRACE(statement + " " + b);
    std::string name = std::string(b).substr(std::string(b).find(' ') + 1);
    name = name.substr(0, name.find('"'));
    try {
      buildSceneText(parameterScene(statement, b));
      ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.location().line, 3) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace candela::test
