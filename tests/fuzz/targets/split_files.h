// The parser fuzzer's input format: several scene files in one input, so that Include and
// spectrum files are resolved from memory. Lines "#file NAME" (a comment to the scene language)
// start each file after the first; the first is /fuzz/main.pbrt and NAME is relative to /fuzz.
//   Include "geometry.pbrt"
//   #file geometry.pbrt
//   Shape "sphere"
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace candela::fuzz {

inline constexpr const char* kMainFile = "/fuzz/main.pbrt";

// Files by lexically normal absolute path. A later file of the same name replaces an earlier one.
std::map<std::string, std::string> splitFiles(std::string_view input);

}  // namespace candela::fuzz
