// A film's per-pixel sums (Film::PixelSums) carried through an image file, for renders split by
// sample range: each piece stores its sums, and adding the pieces' sums gives the sums of the
// whole render, hence its image. EXR holds no doubles, so each double sum d is stored as two
// 32-bit floats, hi = float(d) and lo = float(d - hi): together they keep d to 2^-48 relative.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/image_buffer.h"
#include "film/film.h"

namespace candela {

// The channels appendFilmSums adds ("sums.wR.hi", "sums.wR.lo", ...).
std::vector<std::string> filmSumChannelNames();

// Adds the sum channels of every pixel of image's data window (the film's pixel bounds, as
// Film::image gives them). Throws std::invalid_argument if image is not the film's pixel bounds.
void appendFilmSums(const Film& film, ImageBuffer& image);

// Adds the sums stored in image (at its data window) to film's pixels. Throws
// std::invalid_argument when image lacks a sum channel or reaches outside the film's pixels.
void addFilmSums(const ImageBuffer& image, Film& film);

}  // namespace candela
