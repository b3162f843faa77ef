#include "accel/accelerator_plugins.h"

#include <span>
#include <string>

#include "accel/bvh/bvh_aggregate.h"
#include "accel/embree/embree_aggregate.h"
#include "accel/grid/grid_aggregate.h"
#include "accel/kdtree/kdtree_aggregate.h"

namespace candela {

namespace {

// Builds T over whichever of the input's two forms is set, with the given construction options.
template <class T, class... Options>
std::unique_ptr<Aggregate> build(const AcceleratorInput& in, const Options&... options) {
  if (in.geometry) return std::make_unique<T>(*in.geometry, options...);
  return std::make_unique<T>(std::span<const Primitive>(*in.primitives), options...);
}

std::unique_ptr<Aggregate> createEmbree(const AcceleratorInput& in, const ParamSet& /*params*/,
                                        const FileLoc& /*loc*/) {
  if (in.geometry) return std::make_unique<EmbreeAggregate>(in.device, *in.geometry);
  return std::make_unique<EmbreeAggregate>(in.device, *in.primitives);
}

std::unique_ptr<Aggregate> createBvh(const AcceleratorInput& in, const ParamSet& params,
                                     const FileLoc& loc) {
  BvhParams p;
  p.maxNodePrims = params.getOneInt("maxnodeprims", p.maxNodePrims, ValueRange::atLeast(1), loc);
  std::string method =
      params.getOneString("splitmethod", "sah", {"sah", "middle", "equal", "hlbvh"}, loc);
  if (method == "middle")
    p.splitMethod = BvhSplitMethod::Middle;
  else if (method == "equal")
    p.splitMethod = BvhSplitMethod::Equal;
  else  // "sah", and "hlbvh", which builds the same kind of tree, faster
    p.splitMethod = BvhSplitMethod::Sah;
  return build<BvhAggregate>(in, p);
}

std::unique_ptr<Aggregate> createKdTree(const AcceleratorInput& in, const ParamSet& params,
                                        const FileLoc& loc) {
  KdTreeParams p;
  p.intersectCost = params.getOneInt("intersectcost", p.intersectCost, ValueRange::atLeast(0), loc);
  p.traversalCost = params.getOneInt("traversalcost", p.traversalCost, ValueRange::atLeast(0), loc);
  // The draft's App. C lists "integer emptybonus" with default 0.2 (inventory §24); pbrt-v2
  // reads a float. Either type is taken.
  const ParamItem* bonus = params.find("emptybonus");
  if (bonus && bonus->type == ParamType::Integer && bonus->ints.size() == 1)
    p.emptyBonus = Float(bonus->ints[0]);
  else
    p.emptyBonus = params.getOneFloat("emptybonus", p.emptyBonus);
  params.requireInRange("emptybonus", p.emptyBonus, ValueRange::within(0, 1), loc);
  p.maxPrims = params.getOneInt("maxprims", p.maxPrims, ValueRange::atLeast(1), loc);
  p.maxDepth = params.getOneInt("maxdepth", p.maxDepth);
  return build<KdTreeAggregate>(in, p);
}

std::unique_ptr<Aggregate> createGrid(const AcceleratorInput& in, const ParamSet& params,
                                      const FileLoc& /*loc*/) {
  // Read (so that it is not reported unused) and ignored: nothing is left to refine.
  params.find("refineimmediately");
  return build<GridAggregate>(in);
}

constexpr ParamSpec kBvhParams[] = {
    {"maxnodeprims", "integer", "4", "", "at least 1", kPbrt, "most primitives in a leaf"},
    {"splitmethod", "string", "sah", "", "one of sah, middle, equal, hlbvh", kPbrt,
     "how nodes are split (pbrt-v3's hlbvh builds sah)"},
};

constexpr ParamSpec kKdTreeParams[] = {
    {"intersectcost", "integer", "80", "", "at least 0", kAllDialects,
     "cost of a primitive test, in the split heuristic"},
    {"traversalcost", "integer", "1", "", "at least 0", kAllDialects,
     "cost of a node step, in the split heuristic"},
    {"emptybonus", "float", "0.2", "", "within [0, 1]", kAllDialects,
     "heuristic bonus for an empty side (the draft's 0.2; also read as an integer)"},
    {"maxprims", "integer", "1", "", "at least 1", kAllDialects,
     "primitives below which a node is a leaf"},
    {"maxdepth", "integer", "-1", "", "", kAllDialects,
     "depth limit; 0 or less: round(8 + 1.3 log2 N)"},
};

constexpr ParamSpec kGridParams[] = {
    {"refineimmediately", "bool", "false", "", "", kLrt | kPbrtV2,
     "accepted, no effect: nothing is left to refine (also read as an integer)"},
};

const AcceleratorPlugin kAccelerators[] = {
    {{"accelerator", "embree", kCandela, "Embree's BVHs, candela's default (not in the books)", {}},
     createEmbree},
    {{"accelerator", "bvh", kPbrt, "bounding volume hierarchy (pbrt 2e §4.4)", kBvhParams},
     createBvh},
    {{"accelerator", "kdtree", kAllDialects,
      "kd-tree built by the surface area heuristic (pbrt 2e §4.5)", kKdTreeParams},
     createKdTree},
    {{"accelerator", "grid", kLrt | kPbrtV2, "uniform grid of voxels (pbrt 2e §4.3)", kGridParams},
     createGrid},
};

}  // namespace

std::span<const AcceleratorPlugin> acceleratorPlugins() { return kAccelerators; }

}  // namespace candela
