#include "fuzz/targets/split_files.h"

#include <filesystem>

namespace candela::fuzz {

std::map<std::string, std::string> splitFiles(std::string_view input) {
  constexpr std::string_view kMarker = "#file ";
  std::map<std::string, std::string> files;
  std::string name = kMainFile;
  std::string text;
  size_t pos = 0;
  while (pos < input.size()) {
    size_t end = input.find('\n', pos);
    end = end == std::string_view::npos ? input.size() : end + 1;
    std::string_view line = input.substr(pos, end - pos);
    pos = end;
    if (line.starts_with(kMarker)) {
      files[name] = std::move(text);
      text.clear();
      std::string_view rest = line.substr(kMarker.size());
      while (!rest.empty() && (rest.back() == '\n' || rest.back() == '\r')) rest.remove_suffix(1);
      name = (std::filesystem::path("/fuzz") / std::string(rest)).lexically_normal().string();
    } else {
      text.append(line);
    }
  }
  files[name] = std::move(text);
  return files;
}

}  // namespace candela::fuzz
