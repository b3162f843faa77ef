// A fresh directory per test, named after the test and the process (so that parallel ctest runs
// never share one), removed with everything in it when the test ends.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace candela {

class TempDir {
 public:
  // prefix: what the tests are about ("io", "ply"...), for someone looking in /tmp.
  explicit TempDir(const std::string& prefix) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "candela-" + prefix + "-" + info->test_suite_name() + "-" + info->name() +
                       "-" + std::to_string(::getpid());
    // Parameterised tests' names hold slashes ("Long/Suite", "Test/param"): one directory.
    std::replace(name.begin(), name.end(), '/', '_');
    dir_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Writes bytes to the file name in the directory; returns its path.
  std::string write(const std::string& name, const std::string& bytes) const {
    std::string p = path(name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  // Every entry of the directory, to catch stray temporary files.
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir_))
      names.insert(e.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path dir_;
};

}  // namespace candela
