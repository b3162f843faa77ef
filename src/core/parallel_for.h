// body(i) for every i in [begin, end), in parallel on an arena's threads (tbb::parallel_for, whose
// order of bodies is unspecified): what precedes the call happens before every body, and every
// body before the return, as oneTBB guarantees; both orders are declared to ThreadSanitizer
// (core/happens_before.h). Bodies are not ordered with each other, so races between them show.
#pragma once

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

#include "core/happens_before.h"

namespace candela {

namespace detail {

// Declares its order when the scope ends, also when a body throws (an interrupted render).
struct ReleaseOrderAtExit {
  const void* address;
  ~ReleaseOrderAtExit() { releaseOrder(address); }
};
struct AcquireOrderAtExit {
  const void* address;
  ~AcquireOrderAtExit() { acquireOrder(address); }
};

// The loop's two orders live at two addresses: this object's (before the loop -> each body) and
// the body's (each body -> after the loop). oneTBB's index form keeps a reference to this object,
// so `this` is known to a body before it reads anything another thread wrote.
template <typename Body>
struct OrderedBody {
  const Body& body;
  template <typename Index>
  void operator()(Index i) const {
    acquireOrder(this);
    ReleaseOrderAtExit done{&body};
    body(i);
  }
};

}  // namespace detail

// The same with oneTBB's partitioner given: tbb::simple_partitioner hands out one index at a
// time, so no thread holds a run of them while another has none.
template <typename Index, typename Body, typename Partitioner>
void parallelFor(tbb::task_arena& arena, Index begin, Index end, const Body& body,
                 const Partitioner& partitioner) {
  const detail::OrderedBody<Body> ordered{body};
  releaseOrder(&ordered);
  detail::AcquireOrderAtExit joined{&body};
  arena.execute([&] { tbb::parallel_for(begin, end, ordered, partitioner); });
}

template <typename Index, typename Body>
void parallelFor(tbb::task_arena& arena, Index begin, Index end, const Body& body) {
  parallelFor(arena, begin, end, body, tbb::auto_partitioner());
}

}  // namespace candela
