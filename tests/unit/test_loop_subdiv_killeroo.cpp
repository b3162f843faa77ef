// The killeroo (pbrt-v2's scenes: a "loopsubdiv" shape with a few thousand faces) refined by our
// code and by OpenSubdiv 3.5: issue 4's large cross-check case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "shapes/opensubdiv_loop.h"

namespace candela {
namespace {

// The numbers in the bracket after `key` in text.
std::vector<double> numbersAfter(const std::string& text, const std::string& key) {
  size_t at = text.find(key);
  if (at == std::string::npos) return {};
  size_t open = text.find('[', at), close = text.find(']', open);
  std::istringstream in(text.substr(open + 1, close - open - 1));
  std::vector<double> out;
  for (double x; in >> x;) out.push_back(x);
  return out;
}

TEST(LoopSubdivKilleroo, MatchesOpenSubdiv) {
  std::ifstream file(std::string(CANDELA_SHARED_SCENES_DIR) + "/pbrt-v2/geometry/killeroo.pbrt");
  if (!file) GTEST_SKIP() << "no killeroo.pbrt in the shared scenes";
  std::stringstream text;
  text << file.rdbuf();
  LoopMesh control;
  for (double i : numbersAfter(text.str(), "\"integer indices\""))
    control.indices.push_back(int(i));
  std::vector<double> p = numbersAfter(text.str(), "\"point P\"");
  for (size_t i = 0; i + 2 < p.size(); i += 3)
    control.p.emplace_back(Float(p[i]), Float(p[i + 1]), Float(p[i + 2]));
  ASSERT_GT(control.faceCount(), 1000);
  Point3f lo = control.p[0], hi = control.p[0];
  for (const Point3f& q : control.p)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], q[i]), hi[i] = std::max(hi[i], q[i]);
  Float tolerance = 1e-5f * distance(lo, hi);
  const LoopRules rules{LoopRules::Loop, LoopRules::BSpline};
  // Levels 1 and 2 (level 3 takes 5 s here). Normals are compared inside only: at the killeroo's
  // boundary vertices with six faces the two normals are ill-conditioned (our own normal moves by
  // 5e-3 rad at level 3 when fed OpenSubdiv's float positions, 3e-5 away from ours), and differ by
  // 4.5e-4 rad at level 1, 1.8e-3 at 2, 6.8e-3 at 3: printed, not asserted.
  for (int levels = 1; levels <= 2; ++levels) {
    SCOPED_TRACE("level " + std::to_string(levels));
    LoopMesh ours = refineLoop(control, levels, rules);
    LoopTopology topology = buildLoopTopology(ours, {}, "t");
    LoopLimit limit = loopLimit(ours, topology, rules);
    OsdLoopResult osd = refineLoopOpenSubdiv(control, levels, OsdBoundary::EdgeOnly);
    ASSERT_EQ(ours.p.size(), osd.refined.p.size());
    Float worstP = 0, worstLimit = 0, worstAngle = 0, worstBoundaryAngle = 0;
    int boundary = 0;
    for (size_t v = 0; v < ours.p.size(); ++v) {
      int o = osd.fromOurs[v];
      worstP = std::max(worstP, distance(ours.p[v], osd.refined.p[o]));
      worstLimit = std::max(worstLimit, distance(limit.p[v], osd.limitP[o]));
      Normal3f a = limit.n[v], b = osd.limitN[o];
      Float angle = std::atan2(cross(a, b).length(), dot(a, b));
      if (topology.boundary[v])
        ++boundary, worstBoundaryAngle = std::max(worstBoundaryAngle, angle);
      else
        worstAngle = std::max(worstAngle, angle);
    }
    EXPECT_LE(worstP, tolerance);
    EXPECT_LE(worstLimit, tolerance);
    EXPECT_LT(worstAngle, 1e-3f);
    std::printf(
        "killeroo level %d: %zu vertices, worst |dp| %.3g, |dlimit| %.3g (of diagonal %.3g), "
        "normal angle %.3g rad inside, %.3g on the %d boundary vertices\n",
        levels, ours.p.size(), worstP, worstLimit, distance(lo, hi), worstAngle, worstBoundaryAngle,
        boundary);
  }
}

}  // namespace
}  // namespace candela
