// Lens description files (pbrt 3e §6.4.1, pbrt-v3's format): one interface per line, the front
// (scene side) first, four numbers in millimetres but the index: curvature radius (0: the
// aperture stop), thickness to the next interface, index of refraction of the medium behind it
// (0 or 1: air), aperture diameter. Numbers are separated by white space or commas; '#' starts a
// comment to the end of the line; blank lines are skipped.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cameras/lens_system.h"

namespace candela {

// At most this many interfaces: building the camera traces rays through each (20,000 took 11 s),
// so a huge file would all but hang the render before its first sample.
constexpr size_t kMaxLensInterfaces = 1000;

// The interfaces of the file at path, converted to metres. Throws FileError naming the path (and
// "path:line" for a line that is not four numbers or holds an impossible value: a negative
// thickness or index, an aperture that is not positive or is wider than its sphere, or one
// interface past kMaxLensInterfaces) when the file is missing, unreadable or has no interface.
std::vector<LensInterface> readLensFile(const std::string& path);

}  // namespace candela
