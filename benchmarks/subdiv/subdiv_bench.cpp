// candela_subdiv_bench: Loop subdivision, our code (shapes/loop_subdiv.h) against OpenSubdiv 3.5
// (Far), on the killeroo's control mesh and an icosahedron, levels 1 to 5 (issue 4). Per mesh,
// level and producer: wall time (median of the repeats) of the refinement and of the limit stage,
// and the peak heap bytes over the run above what was live before it. Both producers make the
// same output: the last level's triangles, their vertices' limit positions and unit normals.
// Prints a Markdown table and optionally writes CSV. A program to run by hand: times depend on the
// machine and its load, so nothing here asserts them.
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "heap_counter.h"
#include "shapes/loop_subdiv.h"

using namespace candela;
using namespace candela::bench;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One producer's run. "refine" ends when the last level's positions and the topology the limit
// needs exist (OpenSubdiv builds that topology inside RefineUniform; we build it after the last
// level, so our refine includes that buildLoopTopology); "limit" makes the renderer's output.
struct Run {
  double refineSeconds = 0, limitSeconds = 0;
  double topologySeconds = 0;  // ours only: the part of refine spent in buildLoopTopology
  std::size_t peakBytes = 0;
  std::size_t vertices = 0, faces = 0;
  // The mean of the limit positions: the vertices are numbered differently by the two, but this
  // does not depend on the numbering, and catches a producer that computed the wrong surface.
  double centroid[3] = {0, 0, 0};
};

// The point type of LoopMesh, and so the precision both producers compute in: OpenSubdiv's
// primvars are made of the same scalar, so the comparison stays like for like if it changes.
using MeshPoint = decltype(LoopMesh::p)::value_type;
using Scalar = decltype(MeshPoint::x);

// What the renderer keeps of either producer.
struct Output {
  std::vector<MeshPoint> p;
  std::vector<Normal3f> n;
  std::vector<int> indices;
};

// Fills run's sizes and centroid from out (after the timing and the peak are taken).
void describe(const Output& out, Run& run) {
  run.vertices = out.p.size();
  run.faces = out.indices.size() / 3;
  for (const MeshPoint& q : out.p) {
    run.centroid[0] += q.x / double(out.p.size());
    run.centroid[1] += q.y / double(out.p.size());
    run.centroid[2] += q.z / double(out.p.size());
  }
}

// The same rules as OpenSubdiv's (loop_subdiv.h), so the two do the same arithmetic.
const LoopRules kRules{LoopRules::Loop, LoopRules::BSpline};

Run runOurs(const LoopMesh& control, int levels) {
  Run run;
  std::size_t before = liveHeapBytes();
  resetHeapPeak();
  // refineLoop's steps spelled out, as loop_subdiv_shape.cpp runs them, so that the time spent
  // building topology (validation included) can be told from the time spent applying the masks.
  Clock::time_point start = Clock::now(), step = start;
  LoopTopology topology = buildLoopTopology(control, {}, "bench");
  run.topologySeconds += secondsSince(step);
  LoopMesh mesh = control;
  for (int level = 0; level < levels; ++level) {
    mesh = refineLoopOnce(mesh, topology, kRules);
    step = Clock::now();
    topology = buildLoopTopology(mesh, {}, "bench");
    run.topologySeconds += secondsSince(step);
  }
  run.refineSeconds = secondsSince(start);
  start = Clock::now();
  LoopLimit limit = loopLimit(mesh, topology, kRules);
  Output out{std::move(limit.p), std::move(limit.n), std::move(mesh.indices)};
  run.limitSeconds = secondsSince(start);
  run.peakBytes = peakHeapBytes() - before;
  describe(out, run);
  return run;
}

// The primvar type PrimvarRefiner interpolates: it needs Clear and AddWithWeight.
struct OsdPoint {
  Scalar x = 0, y = 0, z = 0;
  void Clear(void* = nullptr) { x = y = z = 0; }
  void AddWithWeight(const OsdPoint& s, Scalar w) { x += w * s.x, y += w * s.y, z += w * s.z; }
};

Run runOpenSubdiv(const LoopMesh& control, int levels) {
  using namespace OpenSubdiv;
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Run run;
  std::size_t before = liveHeapBytes();
  resetHeapPeak();
  Clock::time_point start = Clock::now();
  // Boundaries as creases, with no corners pinned: the rules ours implements.
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  std::vector<int> counts(control.faceCount(), 3);
  Far::TopologyDescriptor desc;
  desc.numVertices = int(control.p.size());
  desc.numFaces = control.faceCount();
  desc.numVertsPerFace = counts.data();
  desc.vertIndicesPerFace = control.indices.data();
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(Sdc::SCHEME_LOOP, sdc)));
  if (!refiner) {
    std::fprintf(stderr, "ERROR: OpenSubdiv rejected the control mesh\n");
    std::exit(1);
  }
  // Limit() needs the last level's full topology, or it leaves its output at zero.
  Far::TopologyRefiner::UniformOptions options(levels);
  options.fullTopologyInLastLevel = true;
  refiner->RefineUniform(options);
  std::vector<OsdPoint> p(control.p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    p[i] = {control.p[i].x, control.p[i].y, control.p[i].z};
  // Weights in the same precision as the points (PrimvarRefiner is the float instance).
  Far::PrimvarRefinerReal<Scalar> primvars(*refiner);
  for (int level = 1; level <= levels; ++level) {
    std::vector<OsdPoint> next(refiner->GetLevel(level).GetNumVertices());
    primvars.Interpolate(level, p, next);
    p.swap(next);
  }
  run.refineSeconds = secondsSince(start);

  start = Clock::now();
  std::vector<OsdPoint> limit(p.size()), tan1(p.size()), tan2(p.size());
  primvars.Limit(p, limit, tan1, tan2);
  Output out;
  out.p.reserve(p.size());
  out.n.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    out.p.emplace_back(limit[i].x, limit[i].y, limit[i].z);
    const OsdPoint &a = tan1[i], &b = tan2[i];
    Scalar nx = a.y * b.z - a.z * b.y, ny = a.z * b.x - a.x * b.z, nz = a.x * b.y - a.y * b.x;
    Scalar length = std::sqrt(nx * nx + ny * ny + nz * nz);
    out.n.push_back(length > 0
                        ? Normal3f(Float(nx / length), Float(ny / length), Float(nz / length))
                        : Normal3f());
  }
  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  out.indices.reserve(3 * std::size_t(last.GetNumFaces()));
  for (int f = 0; f < last.GetNumFaces(); ++f)
    for (int v : last.GetFaceVertices(f)) out.indices.push_back(v);
  run.limitSeconds = secondsSince(start);
  run.peakBytes = peakHeapBytes() - before;
  describe(out, run);
  return run;
}

// The numbers in the bracket after key in text (the pbrt file's parameter lists).
std::vector<double> numbersAfter(const std::string& text, const std::string& key) {
  std::size_t at = text.find(key);
  if (at == std::string::npos) return {};
  std::size_t open = text.find('[', at), close = text.find(']', open);
  if (open == std::string::npos || close == std::string::npos) return {};
  std::istringstream in(text.substr(open + 1, close - open - 1));
  std::vector<double> out;
  for (double x; in >> x;) out.push_back(x);
  return out;
}

LoopMesh readKilleroo(const std::string& path) {
  std::ifstream file(path);
  if (!file) {
    std::fprintf(stderr, "ERROR: cannot read %s (see --killeroo)\n", path.c_str());
    std::exit(1);
  }
  std::stringstream text;
  text << file.rdbuf();
  LoopMesh mesh;
  for (double i : numbersAfter(text.str(), "\"integer indices\"")) mesh.indices.push_back(int(i));
  std::vector<double> p = numbersAfter(text.str(), "\"point P\"");
  for (std::size_t i = 0; i + 2 < p.size(); i += 3)
    mesh.p.emplace_back(Float(p[i]), Float(p[i + 1]), Float(p[i + 2]));
  if (mesh.p.empty() || mesh.indices.empty()) {
    std::fprintf(stderr, "ERROR: no \"point P\" or \"integer indices\" in %s\n", path.c_str());
    std::exit(1);
  }
  return mesh;
}

// The regular icosahedron on (0, ±1, ±φ) and its cyclic permutations: its faces are the vertex
// triples at mutual distance 2, each wound counter-clockwise seen from outside.
LoopMesh icosahedron() {
  const Float phi = (1 + std::sqrt(Float(5))) / 2;
  std::vector<Point3f> p;
  for (Float a : {-1, 1})
    for (Float b : {-phi, phi}) {
      p.emplace_back(0, a, b);
      p.emplace_back(a, b, 0);
      p.emplace_back(b, 0, a);
    }
  LoopMesh mesh;
  for (const Point3f& q : p) mesh.p.emplace_back(q);
  auto isEdge = [&](int i, int j) { return std::abs(distance(p[i], p[j]) - 2) < 1e-3f; };
  int n = int(p.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        if (!isEdge(i, j) || !isEdge(j, k) || !isEdge(i, k)) continue;
        Vector3f normal = cross(p[j] - p[i], p[k] - p[i]);
        bool outward = dot(normal, p[i] - Point3f(0, 0, 0)) > 0;
        for (int v : {i, outward ? j : k, outward ? k : j}) mesh.indices.push_back(v);
      }
  return mesh;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

// The medians of the repeats; peak bytes the largest seen (they repeat exactly in practice).
struct Summary {
  double refine = 0, limit = 0, total = 0, topology = 0;
  std::size_t peakBytes = 0, vertices = 0, faces = 0;
  double centroid[3] = {0, 0, 0};
};

Summary summarize(const std::vector<Run>& runs) {
  std::vector<double> refine, limit, total, topology;
  Summary s;
  for (const Run& r : runs) {
    refine.push_back(r.refineSeconds);
    topology.push_back(r.topologySeconds);
    limit.push_back(r.limitSeconds);
    total.push_back(r.refineSeconds + r.limitSeconds);
    s.peakBytes = std::max(s.peakBytes, r.peakBytes);
  }
  s.refine = median(refine);
  s.limit = median(limit);
  s.topology = median(topology);
  s.total = median(total);
  s.vertices = runs.back().vertices;
  s.faces = runs.back().faces;
  for (int i = 0; i < 3; ++i) s.centroid[i] = runs.back().centroid[i];
  return s;
}

// Bytes as KB below a megabyte, else MB.
std::string memoryText(std::size_t bytes) {
  char buf[32];
  if (bytes < 1048576)
    std::snprintf(buf, sizeof buf, "%.1f KB", double(bytes) / 1024.0);
  else
    std::snprintf(buf, sizeof buf, "%.1f MB", double(bytes) / 1048576.0);
  return buf;
}

// Seconds as milliseconds with about three significant digits (the table spans 10^-2 to 10^4).
std::string msText(double seconds) {
  double ms = 1e3 * seconds;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", ms >= 100 ? 0 : ms >= 10 ? 1 : ms >= 1 ? 2 : 3, ms);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  std::string killerooPath =
      std::string(CANDELA_SOURCE_DIR) + "/../shared/scenes/pbrt-v2/geometry/killeroo.pbrt";
  std::string csvPath;
  int repeats = 3, topRepeats = 0, minLevel = 1, maxLevel = 5;
  CLI::App app{"candela_subdiv_bench: Loop subdivision time and memory, ours against OpenSubdiv"};
  app.add_option("--killeroo", killerooPath, "pbrt-v2's killeroo.pbrt (its loopsubdiv shape)");
  app.add_option("--repeats", repeats, "Runs per measurement; the median counts")
      ->check(CLI::PositiveNumber);
  app.add_option("--top-repeats", topRepeats,
                 "Runs at the highest level (default: --repeats), which takes the longest")
      ->check(CLI::PositiveNumber);
  app.add_option("--min-level", minLevel, "First level")->check(CLI::Range(1, 6));
  app.add_option("--max-level", maxLevel, "Last level")->check(CLI::Range(1, 6));
  app.add_option("--csv", csvPath, "Also write the results as CSV here");
  CLI11_PARSE(app, argc, argv);
  if (topRepeats == 0) topRepeats = repeats;

  struct Named {
    std::string name;
    LoopMesh mesh;
    double size = 0;  // the diagonal of the control points' bounding box
  };
  std::vector<Named> meshes;
  meshes.push_back({"killeroo", readKilleroo(killerooPath)});
  meshes.push_back({"icosahedron", icosahedron()});
  for (Named& m : meshes) {
    double lo[3] = {m.mesh.p[0].x, m.mesh.p[0].y, m.mesh.p[0].z}, hi[3] = {lo[0], lo[1], lo[2]};
    for (const MeshPoint& q : m.mesh.p) {
      double c[3] = {q.x, q.y, q.z};
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], c[i]), hi[i] = std::max(hi[i], c[i]);
    }
    m.size = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  }

  std::ofstream csv;
  if (!csvPath.empty()) {
    csv.open(csvPath);
    csv << "mesh,control_faces,level,producer,vertices,faces,repeats,refine_s,topology_s,limit_s,"
           "total_s,peak_heap_bytes\n";
  }
  std::printf(
      "| mesh | level | vertices | faces | ours refine (topology) / limit / total (ms) | "
      "OpenSubdiv refine / limit / total (ms) | ours peak heap | OpenSubdiv peak heap | time "
      "ours/OSD | heap ours/OSD |\n|---|---|---|---|---|---|---|---|---|---|\n");
  bool mismatch = false;
  for (const Named& m : meshes) {
    for (int level = minLevel; level <= maxLevel; ++level) {
      int n = level == maxLevel ? topRepeats : repeats;
      std::vector<Run> ours, osd;
      // Alternating, so drift in the machine's load affects both alike.
      for (int i = 0; i < n; ++i) {
        ours.push_back(runOurs(m.mesh, level));
        osd.push_back(runOpenSubdiv(m.mesh, level));
      }
      Summary a = summarize(ours), b = summarize(osd);
      if (a.vertices != b.vertices || a.faces != b.faces) {
        std::fprintf(stderr,
                     "ERROR: %s level %d: ours made %zu vertices and %zu faces, OpenSubdiv %zu "
                     "and %zu\n",
                     m.name.c_str(), level, a.vertices, a.faces, b.vertices, b.faces);
        mismatch = true;
      }
      double offset = std::hypot(a.centroid[0] - b.centroid[0], a.centroid[1] - b.centroid[1],
                                 a.centroid[2] - b.centroid[2]);
      if (!(offset <= 1e-4 * m.size)) {
        std::fprintf(stderr,
                     "ERROR: %s level %d: the mean limit positions differ by %g (mesh size %g)\n",
                     m.name.c_str(), level, offset, m.size);
        mismatch = true;
      }
      std::printf(
          "| %s | %d | %zu | %zu | %s (%s) / %s / %s | %s / %s / %s | %s | %s | %.2f | %.2f |\n",
          m.name.c_str(), level, a.vertices, a.faces, msText(a.refine).c_str(),
          msText(a.topology).c_str(), msText(a.limit).c_str(), msText(a.total).c_str(),
          msText(b.refine).c_str(), msText(b.limit).c_str(), msText(b.total).c_str(),
          memoryText(a.peakBytes).c_str(), memoryText(b.peakBytes).c_str(), a.total / b.total,
          double(a.peakBytes) / double(b.peakBytes));
      std::fflush(stdout);
      if (csv.is_open())
        for (const auto& [producer, s] : {std::pair{"ours", a}, std::pair{"opensubdiv", b}})
          csv << m.name << ',' << m.mesh.faceCount() << ',' << level << ',' << producer << ','
              << s.vertices << ',' << s.faces << ',' << n << ',' << s.refine << ',' << s.topology
              << ',' << s.limit << ',' << s.total << ',' << s.peakBytes << '\n';
    }
  }
  if (mismatch) {
    std::fprintf(stderr, "ERROR: the producers disagree (see above)\n");
    return 1;
  }
  return 0;
}
