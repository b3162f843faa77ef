// Files of numbers that scenes name (pbrt-v2's ReadFloatFile format): decimal numbers separated
// by white space or commas, '#' starting a comment to the end of the line. Used by spectrum
// files (wavelength-value pairs) and dipolesubsurface's pointsfile; core/number_lines.h reads them
// line by line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace candela {

// Every number of text, in order. Throws FileError naming path and the line for a token that is
// not a finite number.
std::vector<double> parseNumberFile(std::string_view text, const std::string& path);

// The same for the file at path; FileError also when it is missing, not a regular file, or
// unreadable.
std::vector<double> readNumberFile(const std::string& path);

}  // namespace candela
