#include "core/number_file.h"

#include "core/number_lines.h"
#include "core/read_file.h"

namespace candela {

std::vector<double> parseNumberFile(std::string_view text, const std::string& path) {
  std::vector<double> numbers;
  parseNumberLines(text, path, [&](int, const std::vector<double>& line) {
    numbers.insert(numbers.end(), line.begin(), line.end());
  });
  return numbers;
}

std::vector<double> readNumberFile(const std::string& path) {
  return parseNumberFile(readWholeFile(path), path);
}

}  // namespace candela
