#include "scene/number_file.h"

#include "core/number_lines.h"

namespace candela {

std::vector<double> readNumberFile(const std::string& path) {
  std::vector<double> numbers;
  readNumberLines(path, [&](int, const std::vector<double>& line) {
    numbers.insert(numbers.end(), line.begin(), line.end());
  });
  return numbers;
}

}  // namespace candela
