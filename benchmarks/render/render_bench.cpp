// candela_render_bench: how fast candela renders against what Embree alone traces
// (docs/performance.md, "Render speed"). For each case and thread count: candela's render (CPU
// seconds of the whole process over the render, wall seconds, rays by kind), the Embree-only
// ceiling on the same scene (embree_ceiling.h), and
//   fraction = (the CPU seconds the ceiling needs for the rays candela traced, kind by kind)
//              / (candela's CPU seconds),
// which is candela's rays per second as a fraction of the ceiling's at candela's own mix of
// camera, closest-hit and shadow rays. Parallel efficiency at T threads is candela's wall-clock
// rate over T times its one-thread rate; the tail is the time some thread had no tile left.
// Thread counts default to 1, 2, 4, ... up to the machine's cores, so the same command measures
// scaling on 2 or 64 cores. Prints a table and writes CSV.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "accel/embree/embree_device.h"
#include "embree_ceiling.h"
#include "integrators/path.h"
#include "render_cases.h"

using namespace candela;
using namespace candela::bench;

namespace {

double processCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Options {
  std::vector<std::string> cases, scenes;
  std::vector<int> threads;
  int seeds = 1;
  int depth = 5;  // the ceiling's depth when the integrator is not "path"
  int ceilingRuns = 3;
  bool ceiling = true;
  bool ceilingStreams = false;  // also the ceiling with stream queries
  std::string csv;              // empty: no CSV file
};

struct Render {
  double cpuSeconds = 0, wallSeconds = 0, tailSeconds = 0;
  RayStats rays;
  double mean = 0;  // of the image's R, G, B
};

Render render(RenderJob& job, int threads) {
  ProgressiveOptions po;
  po.render.nThreads = threads;
  po.render.quiet = true;
  double cpu = processCpuSeconds();
  RenderResult r = renderJob(job, po).total;
  Render out;
  out.cpuSeconds = processCpuSeconds() - cpu;
  out.wallSeconds = r.seconds;
  out.tailSeconds = r.tailSeconds;
  out.rays = r.rays;
  out.mean = job.film->image().rgbMean();
  return out;
}

// The CPU seconds the ceiling would spend on candela's rays, kind by kind.
double ceilingSecondsFor(const RayStats& rays, const CeilingResult& c) {
  auto seconds = [](uint64_t n, const RayKind& k) {
    return n == 0 ? 0.0 : double(n) / std::max(k.perCpuSecond(), 1e-300);
  };
  return seconds(rays.cameraRays, c.camera) +
         seconds(rays.intersectionRays - rays.cameraRays, c.bounce) +
         seconds(rays.shadowRays, c.shadow);
}

std::vector<int> defaultThreads() {
  int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<int> t;
  for (int n = 1; n < cores; n *= 2) t.push_back(n);
  t.push_back(cores);
  return t;
}

// The best of a few ceiling runs, kind by kind: a ceiling is what Embree can do; other work on
// the machine only ever slows it.
CeilingResult bestCeiling(const EmbreeCeiling& ceiling, const RenderJob& probe,
                          const CeilingOptions& co, int runs) {
  CeilingResult best;
  for (int run = 0; run < runs; ++run) {
    CeilingResult c = ceiling.run(*probe.camera, probe.scene->lights(), co);
    if (run == 0) best = c;
    for (auto kind : {&CeilingResult::camera, &CeilingResult::bounce, &CeilingResult::shadow})
      if ((c.*kind).cpuSeconds < (best.*kind).cpuSeconds) best.*kind = c.*kind;
    best.makingSeconds = std::min(best.makingSeconds, c.makingSeconds);
  }
  return best;
}

void runCase(const RenderCase& c, const Options& o, const EmbreeDevice& device,
             std::ofstream& csv) {
  std::unique_ptr<RenderJob> probe = buildCase(c, 1, device);
  int spp = probe->sampler->samplesPerPixel();
  const auto* path = dynamic_cast<const PathIntegrator*>(probe->integrator.get());
  std::unique_ptr<EmbreeCeiling> ceiling;
  if (o.ceiling) ceiling = std::make_unique<EmbreeCeiling>(device, probe->geometry);
  double oneThreadRate = 0;
  for (int threads : o.threads) {
    std::vector<Render> renders;
    for (int seed = 1; seed <= o.seeds; ++seed) {
      std::unique_ptr<RenderJob> job = buildCase(c, uint64_t(seed), device);
      renders.push_back(render(*job, threads));
    }
    // The median render by CPU time stands for the thread count; the means of all seeds give
    // the image mean and its standard error.
    std::vector<Render> byCpu = renders;
    std::sort(byCpu.begin(), byCpu.end(),
              [](const Render& a, const Render& b) { return a.cpuSeconds < b.cpuSeconds; });
    const Render& r = byCpu[byCpu.size() / 2];
    double mean = 0, var = 0;
    for (const Render& x : renders) mean += x.mean / double(renders.size());
    for (const Render& x : renders) var += (x.mean - mean) * (x.mean - mean);
    double se = renders.size() > 1
                    ? std::sqrt(var / double(renders.size() - 1) / double(renders.size()))
                    : 0;
    uint64_t rays = r.rays.intersectionRays + r.rays.shadowRays;
    double wallRate = double(rays) / r.wallSeconds;
    if (threads == o.threads.front()) oneThreadRate = wallRate / threads;
    double efficiency = wallRate / (threads * oneThreadRate);

    CeilingResult ceil;
    double fraction = 0, scalarBound = 0;
    if (ceiling) {
      CeilingOptions co;
      co.pixels = probe->film->pixelBounds();
      co.spp = spp;
      co.maxDepth = path ? path->maxDepth() : o.depth;
      co.threads = threads;
      ceil = bestCeiling(*ceiling, *probe, co, o.ceilingRuns);
      if (o.ceilingStreams) {
        co.streams = true;
        CeilingResult streams = bestCeiling(*ceiling, *probe, co, o.ceilingRuns);
        auto rate = [](const RayKind& k) { return k.perCpuSecond() / 1e6; };
        auto mix = [](const CeilingResult& x) {
          return x.cpuSeconds() > 0 ? double(x.rays()) / x.cpuSeconds() / 1e6 : 0;
        };
        std::printf(
            "%-15s %3d | ceiling Mrays/thr, one query per ray: cam %.2f bnc %.2f shd %.2f mix "
            "%.2f; stream queries per tile wavefront: cam %.2f bnc %.2f shd %.2f mix %.2f "
            "(x%.3f)\n",
            c.name.c_str(), threads, rate(ceil.camera), rate(ceil.bounce), rate(ceil.shadow),
            mix(ceil), rate(streams.camera), rate(streams.bounce), rate(streams.shadow),
            mix(streams), mix(ceil) > 0 ? mix(streams) / mix(ceil) : 0);
      }
      fraction = ceilingSecondsFor(r.rays, ceil) / r.cpuSeconds;
      scalarBound = ceil.cpuSeconds() / (ceil.cpuSeconds() + ceil.makingSeconds);
    }
    std::printf(
        "%-15s %3d | %7.2f %7.2f %6.2f %6.2f %6.2f %6.3f %6.4f | %6.2f %6.2f %6.2f %6.2f | %5.3f "
        "%5.3f | "
        "%.6f +- %.6f\n",
        c.name.c_str(), threads, r.cpuSeconds, r.wallSeconds, double(rays) / 1e6,
        double(rays) / r.cpuSeconds / 1e6, wallRate / 1e6, efficiency, r.tailSeconds,
        ceil.camera.perCpuSecond() / 1e6, ceil.bounce.perCpuSecond() / 1e6,
        ceil.shadow.perCpuSecond() / 1e6,
        ceil.cpuSeconds() > 0 ? double(ceil.rays()) / ceil.cpuSeconds() / 1e6 : 0, fraction,
        scalarBound, mean, se);
    std::fflush(stdout);
    if (csv.is_open())
      csv << c.name << ',' << threads << ',' << spp << ',' << r.cpuSeconds << ',' << r.wallSeconds
          << ',' << r.rays.cameraRays << ',' << r.rays.intersectionRays - r.rays.cameraRays << ','
          << r.rays.shadowRays << ',' << double(rays) / r.cpuSeconds / 1e6 << ',' << wallRate / 1e6
          << ',' << efficiency << ',' << r.tailSeconds << ',' << ceil.camera.perCpuSecond() / 1e6
          << ',' << ceil.bounce.perCpuSecond() / 1e6 << ',' << ceil.shadow.perCpuSecond() / 1e6
          << ',' << ceil.rays() << ',' << ceil.cpuSeconds() << ',' << ceil.wallSeconds << ','
          << fraction << ',' << ceil.makingSeconds << ',' << scalarBound << ',' << mean << ',' << se
          << ',' << renders.size() << '\n';
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"candela render benchmark: render speed against an Embree-only ceiling"};
  std::vector<RenderCase> cases = standardCases(CANDELA_SOURCE_DIR);
  std::string names;
  for (const RenderCase& c : cases) names += (names.empty() ? "" : ", ") + c.name;
  app.add_option("--cases", o.cases, "cases to run (default all: " + names + ")")->delimiter(',');
  app.add_option("--scenes", o.scenes, "also render these .pbrt files as they are")->delimiter(',');
  app.add_option("--threads", o.threads, "thread counts (default 1, 2, 4, ... all cores)")
      ->delimiter(',');
  app.add_option("--seeds", o.seeds,
                 "renders per thread count, seeds 1..N (median CPU time; the "
                 "image mean's standard error over them)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--depth", o.depth, "the ceiling's path depth when the integrator is not path");
  app.add_option("--ceiling-runs", o.ceilingRuns, "ceiling runs per thread count (the fastest)")
      ->check(CLI::Range(1, 100));
  app.add_flag("!--no-ceiling", o.ceiling, "render only");
  app.add_flag("--ceiling-streams", o.ceilingStreams,
               "also run the ceiling with Embree's stream queries (rtcIntersect1M, "
               "rtcOccluded1M) per tile wavefront, and print both");
  app.add_option("--csv", o.csv, "also write the rows to this CSV file");
  CLI11_PARSE(app, argc, argv);
  if (o.threads.empty()) o.threads = defaultThreads();
  std::vector<RenderCase> run;
  for (const RenderCase& c : cases)
    if (o.cases.empty() || std::find(o.cases.begin(), o.cases.end(), c.name) != o.cases.end())
      run.push_back(c);
  for (const std::string& s : o.scenes) run.push_back({s.substr(s.find_last_of('/') + 1), s, ""});
  try {
    EmbreeDevice device;
    std::ofstream csv;
    if (!o.csv.empty()) {
      csv.open(o.csv);
      if (!csv) throw std::runtime_error("cannot write " + o.csv);
    }
    if (csv.is_open())
      csv << "case,threads,spp,cpu_s,wall_s,camera_rays,bounce_rays,shadow_rays,mrays_per_cpu_s,"
             "mrays_per_wall_s,efficiency,tail_s,ceiling_camera,ceiling_bounce,ceiling_shadow,"
             "ceiling_rays,ceiling_cpu_s,ceiling_wall_s,fraction,ceiling_making_s,scalar_bound,"
             "image_mean,image_mean_se,seeds\n";
    std::printf(
        "Mrays/s per thread = rays / CPU s; fraction = ceiling CPU s for candela's rays / "
        "candela CPU s;\nbound = the fraction of a renderer whose only work between queries is the "
        "ceiling's ray making\n");
    std::printf("%-15s %3s | %7s %7s %6s %6s %6s %6s %6s | %-27s | %5s %5s | %s\n", "case", "thr",
                "CPU s", "wall s", "Mrays", "/thr", "/wall", "effic", "tail s",
                "ceiling cam bnc shd mix /thr", "frac", "bound", "image mean +- se");
    for (const RenderCase& c : run) runCase(c, o, device, csv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela_render_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
