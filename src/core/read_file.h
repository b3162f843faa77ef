// The whole contents of a file that a scene names (an included scene, a spectrum, a measured
// BRDF, a lens): read at once, so that the readers parse bytes in memory and can be given bytes
// from elsewhere (tests, the fuzzers of tests/fuzz).
#pragma once

#include <string>

namespace candela {

// Reads a whole regular file. Throws FileError naming the path when it is missing, a directory or
// not a regular file (a device such as /dev/zero would never end), or unreadable.
std::string readWholeFile(const std::string& path);

}  // namespace candela
