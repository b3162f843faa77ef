// Recursive-descent parser of lrt/pbrt scene files (lrt draft App. C; pbrt-v2's directives, lrt's
// ToneMap/BumpMap/SearchPath, pbrt-v3's Integrator/MakeNamedMedium/MediumInterface/Import/Option).
// Each statement becomes one ParserTarget call; parameter values are checked against their
// declared type and spectral values are converted to RGB here (parser/spectrum_input.h).
//
// Errors are SceneError with file:line:col of the offending token; a top-level file that cannot
// be read is a FileError. No input makes the parser crash or hang.
#pragma once

#include <functional>
#include <string>

#include "core/error.h"
#include "parser/parser_target.h"

namespace candela {

using WarningCallback = std::function<void(const FileLoc&, const std::string&)>;
// Returns the whole contents of a file a scene names (Include, Import, "spectrum" files), given
// its path resolved against the naming file's directory; throws FileError naming the path when
// there is no such file.
using SceneFileReader = std::function<std::string(const std::string& path)>;

// Parses one file ("-" = standard input) into target. Include/Import paths and spectrum files are
// relative to the directory of the file that names them. Several files in sequence are several
// calls; the caller then calls target.endOfInput. Warnings (e.g. an ignored Option) go to warn,
// or to standard error when warn is empty.
void parseFile(const std::string& path, ParserTarget& target, const WarningCallback& warn = {});

// Parses text as if it were the contents of a file called filename (used in locations and to
// resolve relative paths). The files it names are read by readFile when given (the fuzzer and
// tests serve them from memory), else from the filesystem.
void parseString(const std::string& text, const std::string& filename, ParserTarget& target,
                 const WarningCallback& warn = {}, const SceneFileReader& readFile = {});

}  // namespace candela
