// Text files of numbers that scenes name (pbrt-v2's ReadFloatFile format, pbrt-v3's lens files):
// decimal numbers separated by white space or commas, '#' starting a comment to the end of the
// line.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

using NumberLineCallback = std::function<void(int line, const std::vector<double>&)>;

// Calls onLine(line number, its numbers) for each line of text that holds any, in order. Throws
// FileError naming path and the line for a token that is not a number within float range.
void parseNumberLines(std::string_view text, const std::string& path,
                      const NumberLineCallback& onLine);

// The same for the file at path; FileError also when it is missing, not a regular file (a device
// would never end) or unreadable.
void readNumberLines(const std::string& path, const NumberLineCallback& onLine);

}  // namespace candela
