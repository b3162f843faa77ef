// Text files of numbers that scenes name (pbrt-v2's ReadFloatFile format, pbrt-v3's lens files):
// decimal numbers separated by white space or commas, '#' starting a comment to the end of the
// line.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace candela {

// Calls onLine(line number, its numbers) for each line that holds any, in order. Throws FileError
// naming the path when the file is missing, not a regular file (a device would never end) or
// unreadable, and with the line for a token that is not a number within float range.
void readNumberLines(const std::string& path,
                     const std::function<void(int line, const std::vector<double>&)>& onLine);

}  // namespace candela
