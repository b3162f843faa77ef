#include "core/number_lines.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace candela {

void readNumberLines(const std::string& path,
                     const std::function<void(int line, const std::vector<double>&)>& onLine) {
  if (path.find('\0') != std::string::npos)
    throw FileError(path.substr(0, path.find('\0')), "NUL in file name");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw FileError(path,
                    std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  std::string line;
  std::vector<double> numbers;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
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
                                  line.substr(i, std::min<size_t>(end - i, 40)) + "'");
      numbers.push_back(v);
      i = end;
    }
    if (!numbers.empty()) onLine(lineNo, numbers);
  }
  if (in.bad()) throw FileError(path, "read error");
}

}  // namespace candela
