// candela_accel_bench: scenes x aggregates, side by side (DESIGN.md, "Accelerator A/B
// benchmarking"). For each pair: build time, memory of the structure (bytes the reference
// aggregates account for, and the process's resident-set growth over the build, which is the
// only measure Embree's allocations have), and rays per second for camera, diffuse-bounce and
// shadow rays on one thread and on all threads. Then a scaling series on generated meshes of
// 10^3 ... 10^6 triangles: build time and nanoseconds per ray against N.
// Prints tables and writes CSV; tools/plot_accel_scaling.py draws the series.
#include <malloc.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

#include "accel/aggregate_factory.h"
#include "accel/embree/embree_device.h"
#include "bench_scenes.h"
#include "ray_workloads.h"

using namespace candela;
using namespace candela::bench;

namespace {

long residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

double processCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Built {
  std::unique_ptr<Aggregate> aggregate;
  double seconds = 0;        // wall clock
  double cpuSeconds = 0;     // all threads' CPU time (Embree builds in parallel, the others do not)
  long accountedBytes = -1;  // -1: not known (Embree)
  long rssDelta = 0;
};

Built build(const std::string& kind, const BenchScene& scene, const EmbreeDevice& device) {
  Built b;
  malloc_trim(0);
  long before = residentBytes();
  auto start = std::chrono::steady_clock::now();
  double cpuStart = processCpuSeconds();
  b.aggregate = createAggregate(kind, {}, *scene.geometry, device, FileLoc{"bench", 1, 1});
  b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  b.cpuSeconds = processCpuSeconds() - cpuStart;
  b.rssDelta = residentBytes() - before;
  AggregateStats st = b.aggregate->stats();
  if (auto it = st.counts.find("bytes"); it != st.counts.end()) b.accountedBytes = it->second;
  return b;
}

// Bytes as KB or MB ("-" when unknown).
std::string memoryText(long bytes) {
  if (bytes < 0) return "-";
  char buf[32];
  if (bytes < 1048576)
    std::snprintf(buf, sizeof buf, "%.1f KB", bytes / 1024.0);
  else
    std::snprintf(buf, sizeof buf, "%.1f MB", bytes / 1048576.0);
  return buf;
}

std::string mrays(double raysPerSecond) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", raysPerSecond / 1e6);
  return buf;
}

struct Options {
  std::vector<std::string> scenes, aggregates = acceleratorNames();
  std::vector<long> scalingSizes = {1000, 10000, 100000, 1000000};
  long cameraRays = 65536, scalingRays = 32768;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  int repeats = 2;
  std::string csv = "accel_bench.csv", scalingCsv = "accel_scaling.csv", mode = "both";
};

void runTable(const Options& o, const EmbreeDevice& device) {
  std::ofstream csv(o.csv);
  csv << "scene,aggregate,triangles,quadrics,instances,instanced_triangles,build_wall_s,build_cpu_"
         "s,"
         "accounted_bytes,rss_delta_bytes,camera_rays,camera_1t,camera_nt,bounce_rays,bounce_1t,"
         "bounce_nt,shadow_rays,shadow_1t,shadow_nt,threads\n";
  std::printf("Mrays/s: 1 thread timed by its CPU clock, %d threads by the wall clock\n",
              o.threads);
  std::printf("%-18s %-7s %11s %10s %10s | %-15s %-15s %-15s\n", "scene", "accel", "build cpu s",
              "accounted", "rss growth", "camera 1/N", "bounce 1/N", "shadow 1/N");
  for (const std::string& name : o.scenes) {
    std::unique_ptr<BenchScene> scene = makeScene(name, device);
    Built reference = build("embree", *scene, device);
    RaySets rays = makeRays(*scene, *reference.aggregate, o.cameraRays, 1);
    reference = Built();
    long embreeHits = -1;
    for (const std::string& kind : o.aggregates) {
      Built b = build(kind, *scene, device);
      TraceResult r[3][2];
      const std::vector<Ray>* sets[3] = {&rays.camera, &rays.bounce, &rays.shadow};
      for (int w = 0; w < 3; ++w)
        for (int t = 0; t < 2; ++t)
          r[w][t] = trace(*b.aggregate, *sets[w], w == 2, t == 0 ? 1 : o.threads, o.repeats);
      std::printf("%-18s %-7s %11.3f %10s %10s | %6s / %-6s %6s / %-6s %6s / %-6s\n",
                  scene->name.c_str(), kind.c_str(), b.cpuSeconds,
                  memoryText(b.accountedBytes).c_str(), memoryText(b.rssDelta).c_str(),
                  mrays(r[0][0].raysPerSecond(rays.camera.size())).c_str(),
                  mrays(r[0][1].raysPerSecond(rays.camera.size())).c_str(),
                  mrays(r[1][0].raysPerSecond(rays.bounce.size())).c_str(),
                  mrays(r[1][1].raysPerSecond(rays.bounce.size())).c_str(),
                  mrays(r[2][0].raysPerSecond(rays.shadow.size())).c_str(),
                  mrays(r[2][1].raysPerSecond(rays.shadow.size())).c_str());
      std::fflush(stdout);
      // The same rays must hit the same things whatever the aggregate.
      long hits = r[0][0].hits + r[1][0].hits + r[2][0].hits;
      if (embreeHits < 0) embreeHits = hits;
      if (std::abs(hits - embreeHits) > 1 + embreeHits / 1000)
        std::fprintf(stderr, "warning: %s on %s: %ld hits, the first aggregate %ld\n", kind.c_str(),
                     scene->name.c_str(), hits, embreeHits);
      csv << scene->name << ',' << kind << ',' << scene->triangles << ',' << scene->quadrics << ','
          << scene->instances << ',' << scene->instancedTriangles << ',' << b.seconds << ','
          << b.cpuSeconds << ',' << b.accountedBytes << ',' << b.rssDelta;
      for (int w = 0; w < 3; ++w)
        csv << ',' << sets[w]->size() << ',' << r[w][0].raysPerSecond(sets[w]->size()) << ','
            << r[w][1].raysPerSecond(sets[w]->size());
      csv << ',' << o.threads << '\n';
    }
  }
  std::printf("wrote %s\n", o.csv.c_str());
}

void runScaling(const Options& o, const EmbreeDevice& device) {
  std::ofstream csv(o.scalingCsv);
  csv << "aggregate,triangles,build_wall_s,build_cpu_s,accounted_bytes,rss_delta_bytes,"
         "camera_ns_per_ray,bounce_ns_per_ray\n";
  std::printf("\n%-7s %10s %11s %10s %12s %12s   (1 thread)\n", "accel", "triangles", "build cpu s",
              "accounted", "camera ns", "bounce ns");
  for (long n : o.scalingSizes) {
    std::unique_ptr<BenchScene> scene = makeScene("mesh-" + std::to_string(n), device);
    Built reference = build("embree", *scene, device);
    RaySets rays = makeRays(*scene, *reference.aggregate, o.scalingRays, 2);
    reference = Built();
    for (const std::string& kind : o.aggregates) {
      Built b = build(kind, *scene, device);
      double cam = trace(*b.aggregate, rays.camera, false, 1, o.repeats).seconds * 1e9 /
                   double(std::max<size_t>(1, rays.camera.size()));
      double bounce = trace(*b.aggregate, rays.bounce, false, 1, o.repeats).seconds * 1e9 /
                      double(std::max<size_t>(1, rays.bounce.size()));
      std::printf("%-7s %10ld %11.3f %10s %12.0f %12.0f\n", kind.c_str(), scene->triangles,
                  b.cpuSeconds, memoryText(b.accountedBytes).c_str(), cam, bounce);
      std::fflush(stdout);
      csv << kind << ',' << scene->triangles << ',' << b.seconds << ',' << b.cpuSeconds << ','
          << b.accountedBytes << ',' << b.rssDelta << ',' << cam << ',' << bounce << '\n';
    }
  }
  std::printf("wrote %s\n", o.scalingCsv.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  o.scenes = generatedSceneNames();
  o.scenes.push_back(std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/cornell-box.pbrt");
  o.scenes.push_back(std::string(CANDELA_SOURCE_DIR) + "/scenes/spheres/spheres.pbrt");
  CLI::App app{"candela_accel_bench: aggregates compared on build time, memory and rays/s"};
  app.add_option("--mode", o.mode, "table, scaling or both")
      ->check(CLI::IsMember({"table", "scaling", "both"}));
  app.add_option("--scenes", o.scenes, "Generated (mesh-N, quadrics, instances, stadium) or .pbrt")
      ->delimiter(',');
  app.add_option("--accels", o.aggregates, "Aggregates to compare")
      ->delimiter(',')
      ->check(CLI::IsMember(acceleratorNames()));
  app.add_option("--rays", o.cameraRays, "Camera rays per scene (bounce and shadow: one per hit)")
      ->check(CLI::PositiveNumber);
  app.add_option("--threads", o.threads, "The 'all threads' count")->check(CLI::PositiveNumber);
  app.add_option("--repeats", o.repeats, "Runs per measurement; the fastest counts")
      ->check(CLI::PositiveNumber);
  app.add_option("--csv", o.csv, "CSV of the table");
  app.add_option("--scaling-sizes", o.scalingSizes, "Triangle counts of the scaling series")
      ->delimiter(',');
  app.add_option("--scaling-rays", o.scalingRays, "Camera rays per scaling step")
      ->check(CLI::PositiveNumber);
  app.add_option("--scaling-csv", o.scalingCsv, "CSV of the scaling series");
  CLI11_PARSE(app, argc, argv);
  try {
    EmbreeDevice device;
    if (o.mode != "scaling") runTable(o, device);
    if (o.mode != "table") runScaling(o, device);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela_accel_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
