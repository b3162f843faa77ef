#include "core/number_lines.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "core/read_file.h"

namespace candela {

void parseNumberLines(std::string_view text, const std::string& path,
                      const NumberLineCallback& onLine) {
  std::vector<double> numbers;
  int lineNo = 0;
  size_t lineStart = 0;
  while (lineStart < text.size()) {
    size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string_view::npos) lineEnd = text.size();
    std::string_view line = text.substr(lineStart, lineEnd - lineStart);
    lineStart = lineEnd + 1;
    ++lineNo;
    if (size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    numbers.clear();
    size_t i = 0;
    while (i < line.size()) {
      if (std::strchr(" \t\r,\f\v", line[i])) {
        ++i;
        continue;
      }
      size_t end = i;
      while (end < line.size() && !std::strchr(" \t\r,\f\v", line[end])) ++end;
      const char* first = line.data() + i + (line[i] == '+' ? 1 : 0);
      double v = 0;
      auto [ptr, err] = std::from_chars(first, line.data() + end, v);
      if (err != std::errc() || ptr != line.data() + end || !(std::abs(v) <= 3.4e38))
        throw FileError(path, "line " + std::to_string(lineNo) + ": expected a number, found '" +
                                  std::string(line.substr(i, std::min<size_t>(end - i, 40))) + "'");
      numbers.push_back(v);
      i = end;
    }
    if (!numbers.empty()) onLine(lineNo, numbers);
  }
}

void readNumberLines(const std::string& path, const NumberLineCallback& onLine) {
  parseNumberLines(readWholeFile(path), path, onLine);
}

}  // namespace candela
