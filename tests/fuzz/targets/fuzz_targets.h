// The fuzz targets of tests/fuzz: each feeds one input to one reader and checks what the reader
// promises. Expected rejections (SceneError, FileError) are caught; anything else escapes, and a
// broken promise aborts, so libFuzzer reports both. The libFuzzer executables (fuzz_main.cpp)
// and the corpus replay of the unit tests call the same functions.
#pragma once

#include <string_view>

namespace candela::fuzz {

void tokenizer(std::string_view input);  // scene text, token by token
void parser(std::string_view input);     // scene files (split_files.h) through the SceneBuilder
void ply(std::string_view input);        // a PLY mesh
void spd(std::string_view input);        // a .spd spectrum, converted to RGB
void brdf(std::string_view input);       // a pbrt-v2 .brdf table, looked up
void merl(std::string_view input);       // a MERL binary BRDF, looked up
void fourier(std::string_view input);    // a pbrt-v3 Fourier .bsdf table, evaluated and sampled

// Aborts with the message when a reader broke a promise (a check, not an assertion: it stays
// in release builds).
[[noreturn]] void broken(const char* what);

}  // namespace candela::fuzz
