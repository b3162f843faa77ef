#include <cstdio>
#include <cstdlib>

#include "fuzz/targets/fuzz_targets.h"

namespace candela::fuzz {

void broken(const char* what) {
  std::fprintf(stderr, "fuzz: broken promise: %s\n", what);
  std::abort();
}

}  // namespace candela::fuzz
