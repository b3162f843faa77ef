// The fuzzers' seed corpus (tests/fuzz/corpus), including every input a fuzzer once crashed on,
// replayed through the fuzz targets in the ordinary build: each target's checks hold for each.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "fuzz/targets/fuzz_targets.h"
#include "fuzz/targets/split_files.h"

using namespace candela;
namespace fs = std::filesystem;

namespace {

void replay(const std::string& target, const std::function<void(std::string_view)>& run) {
  fs::path dir = fs::path(CANDELA_FUZZ_CORPUS_DIR) / target;
  int n = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    SCOPED_TRACE(e.path().string());
    run(bytes.str());
    ++n;
  }
  EXPECT_GE(n, 3) << "a seed corpus of at least three inputs in " << dir;
}

}  // namespace

TEST(FuzzCorpus, Tokenizer) { replay("tokenizer", fuzz::tokenizer); }
TEST(FuzzCorpus, Parser) { replay("parser", fuzz::parser); }
TEST(FuzzCorpus, Ply) { replay("ply", fuzz::ply); }
TEST(FuzzCorpus, Spd) { replay("spd", fuzz::spd); }
TEST(FuzzCorpus, Brdf) { replay("brdf", fuzz::brdf); }
TEST(FuzzCorpus, Merl) { replay("merl", fuzz::merl); }
TEST(FuzzCorpus, Fourier) { replay("fourier", fuzz::fourier); }

TEST(FuzzCorpus, SplitFilesNamesEachPartUnderFuzz) {
  auto files = fuzz::splitFiles(
      "Include \"a/b.pbrt\"\n#file a/b.pbrt\r\nShape \"disk\"\n#file ../x.spd\n1 2");
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[fuzz::kMainFile], "Include \"a/b.pbrt\"\n");
  EXPECT_EQ(files["/fuzz/a/b.pbrt"], "Shape \"disk\"\n");
  EXPECT_EQ(files["/x.spd"], "1 2");
  EXPECT_EQ(fuzz::splitFiles("").size(), 1u);
}
