// parallelFor (core/parallel_for.h): every index runs once, on the arena's threads; what precedes
// the loop is seen by every body and what the bodies write is seen after it. Under
// ThreadSanitizer, with the CI suppressions (tools/sanitizers/tsan.supp), two bodies writing one
// variable are still reported: the suppressions of oneTBB's internals and the orders declared for
// the loop do not hide races between bodies.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <thread>
#include <vector>

#include "core/parallel_for.h"

namespace candela {
namespace {

TEST(ParallelFor, EveryIndexOnceAndTheWritesAreSeenOnBothSides) {
  tbb::task_arena arena(2);
  const int n = 10000;
  std::vector<int> before(n), after(n, 0);
  for (int i = 0; i < n; ++i) before[i] = 3 * i;
  std::vector<std::thread::id> thread(n);
  parallelFor(arena, 0, n, [&](int i) {
    after[i] += before[i] + 1;
    thread[i] = std::this_thread::get_id();
  });
  for (int i = 0; i < n; ++i) ASSERT_EQ(after[i], 3 * i + 1) << i;
  std::set<std::thread::id> threads(thread.begin(), thread.end());
  EXPECT_LE(threads.size(), 2u);  // the arena's concurrency
  parallelFor(arena, size_t(5), size_t(5), [&](size_t) { ADD_FAILURE() << "empty range"; });
}

#if defined(CANDELA_THREAD_SANITIZER)
// The racy write, in a function of its own so that the report names it.
[[gnu::noinline]] void addToSharedSum(long* sum, int v) { *sum += v; }

// Two bodies, held until both have started (relaxed atomics: no order between them), then both
// write `sum`. The child process reports the race and exits with ThreadSanitizer's status 66.
void raceBetweenTwoBodies() {
  tbb::task_arena arena(2);
  std::atomic<int> started{0};
  long sum = 0;
  parallelFor(arena, 0, 2, [&](int i) {
    started.fetch_add(1, std::memory_order_relaxed);
    auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (started.load(std::memory_order_relaxed) < 2 && std::chrono::steady_clock::now() < giveUp)
      std::this_thread::yield();
    addToSharedSum(&sum, i + 1);
  });
  std::fprintf(stderr, "sum %ld, %d bodies met\n", sum, started.load());
  std::exit(0);
}

TEST(ParallelForDeathTest, ThreadSanitizerStillSeesARaceBetweenBodies) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(raceBetweenTwoBodies(), testing::ExitedWithCode(66),
              "ThreadSanitizer: data race.*#0 [^#]*addToSharedSum");
}
#endif

}  // namespace
}  // namespace candela
