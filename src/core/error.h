// Errors that reach the user: every scene error names file:line:col.
#pragma once

#include <stdexcept>
#include <string>

namespace candela {

struct FileLoc {
  std::string file;  // "-" for standard input
  int line = 1, column = 1;
  // "file:line:col"; just the name when there is no line: the end of a file, or a command-line
  // option ("--spp").
  std::string str() const {
    if (line == 0) return file;
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
  }
};

// Bad input in a scene file or on the command line; what() is the full user-facing message.
class SceneError : public std::runtime_error {
 public:
  SceneError(const FileLoc& loc, const std::string& message)
      : std::runtime_error(loc.str() + ": error: " + message), loc_(loc) {}
  explicit SceneError(const std::string& message) : std::runtime_error("error: " + message) {}
  const FileLoc& location() const { return loc_; }

 private:
  FileLoc loc_;
};

// A file that cannot be read or written; the message names its path.
class FileError : public std::runtime_error {
 public:
  FileError(const std::string& path, const std::string& message)
      : std::runtime_error(path + ": error: " + message) {}
};

}  // namespace candela
