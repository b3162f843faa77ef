#include "accel/aggregate_factory.h"

#include <algorithm>

#include "accel/bvh/bvh_aggregate.h"
#include "accel/embree/embree_aggregate.h"
#include "accel/grid/grid_aggregate.h"
#include "accel/kdtree/kdtree_aggregate.h"

namespace candela {

namespace {

[[noreturn]] void fail(const FileLoc& loc, const std::string& message) {
  // Options set outside any file (the --accel flag, a test) have no location to name.
  if (loc.file.empty()) throw SceneError(message);
  throw SceneError(loc, message);
}

// An integer parameter that must be at least lo.
int intAtLeast(const ParamSet& params, const std::string& name, int def, int lo,
               const FileLoc& loc) {
  int v = params.getOneInt(name, def);
  if (v < lo)
    fail(params.locationOf(name, loc),
         "\"" + name + "\" must be at least " + std::to_string(lo) + ", not " + std::to_string(v));
  return v;
}

KdTreeParams kdTreeParams(const ParamSet& params, const FileLoc& loc) {
  KdTreeParams p;
  p.intersectCost = intAtLeast(params, "intersectcost", p.intersectCost, 0, loc);
  p.traversalCost = intAtLeast(params, "traversalcost", p.traversalCost, 0, loc);
  // The draft's App. C lists "integer emptybonus" with default 0.2 (inventory §24); pbrt-v2
  // reads a float. Either type is taken.
  const ParamItem* bonus = params.find("emptybonus");
  if (bonus && bonus->type == ParamType::Integer && bonus->ints.size() == 1)
    p.emptyBonus = Float(bonus->ints[0]);
  else
    p.emptyBonus = params.getOneFloat("emptybonus", p.emptyBonus);
  if (!(p.emptyBonus >= 0 && p.emptyBonus <= 1))
    fail(params.locationOf("emptybonus", loc), "\"emptybonus\" must lie in [0, 1]");
  p.maxPrims = intAtLeast(params, "maxprims", p.maxPrims, 1, loc);
  p.maxDepth = params.getOneInt("maxdepth", p.maxDepth);
  return p;
}

BvhParams bvhParams(const ParamSet& params, const FileLoc& loc) {
  BvhParams p;
  p.maxNodePrims = intAtLeast(params, "maxnodeprims", p.maxNodePrims, 1, loc);
  std::string method = params.getOneString("splitmethod", "sah");
  if (method == "sah" || method == "hlbvh")  // hlbvh builds the same kind of tree, faster
    p.splitMethod = BvhSplitMethod::Sah;
  else if (method == "middle")
    p.splitMethod = BvhSplitMethod::Middle;
  else if (method == "equal")
    p.splitMethod = BvhSplitMethod::Equal;
  else
    fail(params.locationOf("splitmethod", loc),
         "unknown bvh splitmethod '" + method + "' (known: sah, middle, equal, hlbvh)");
  return p;
}

void readGridParams(const ParamSet& params) {
  // Read (so that it is not reported unused) and ignored: nothing is left to refine.
  params.find("refineimmediately");
}

void checkName(const std::string& name, const FileLoc& loc) {
  if (isAcceleratorName(name)) return;
  std::string list;
  for (const auto& k : acceleratorNames()) list += (list.empty() ? "" : ", ") + k;
  fail(loc, "unknown accelerator '" + name + "' (known: " + list + ")");
}

}  // namespace

const std::vector<std::string>& acceleratorNames() {
  static const std::vector<std::string> names = {"embree", "bvh", "kdtree", "grid"};
  return names;
}

bool isAcceleratorName(const std::string& name) {
  const auto& names = acceleratorNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::unique_ptr<Aggregate> createAggregate(const std::string& nameIn, const ParamSet& params,
                                           const SceneGeometry& geometry,
                                           const EmbreeDevice& device, const FileLoc& loc) {
  std::string name = nameIn.empty() ? "embree" : nameIn;
  checkName(name, loc);
  if (name == "kdtree")
    return std::make_unique<KdTreeAggregate>(geometry, kdTreeParams(params, loc));
  if (name == "bvh") return std::make_unique<BvhAggregate>(geometry, bvhParams(params, loc));
  if (name == "grid") {
    readGridParams(params);
    return std::make_unique<GridAggregate>(geometry);
  }
  return std::make_unique<EmbreeAggregate>(device, geometry);
}

std::unique_ptr<Aggregate> createAggregate(const std::string& nameIn, const ParamSet& params,
                                           const std::vector<Primitive>& primitives,
                                           const EmbreeDevice& device, const FileLoc& loc) {
  std::string name = nameIn.empty() ? "embree" : nameIn;
  checkName(name, loc);
  std::span<const Primitive> prims(primitives);
  if (name == "kdtree") return std::make_unique<KdTreeAggregate>(prims, kdTreeParams(params, loc));
  if (name == "bvh") return std::make_unique<BvhAggregate>(prims, bvhParams(params, loc));
  if (name == "grid") {
    readGridParams(params);
    return std::make_unique<GridAggregate>(prims);
  }
  return std::make_unique<EmbreeAggregate>(device, primitives);
}

}  // namespace candela
