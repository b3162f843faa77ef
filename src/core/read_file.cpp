#include "core/read_file.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"

namespace candela {

std::string readWholeFile(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.find('\0') != std::string::npos)
    throw FileError(path.substr(0, path.find('\0')), "NUL in file name");
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw FileError(path, "no such file");
  if (fs::is_directory(st)) throw FileError(path, "is a directory, not a file");
  if (!fs::is_regular_file(st)) throw FileError(path, "not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw FileError(path, "read error");
  return text;
}

}  // namespace candela
