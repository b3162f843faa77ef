#include "textures/mipmap.h"

#include <stdexcept>

#include "textures/mipmap_filter.h"

namespace candela {

std::optional<WrapMode> parseWrapMode(const std::string& name) {
  if (name == "repeat") return WrapMode::Repeat;
  if (name == "black") return WrapMode::Black;
  if (name == "clamp") return WrapMode::Clamp;
  return std::nullopt;
}

namespace {

Float minOf(Float a, Float b) { return std::min(a, b); }
Float maxOf(Float a, Float b) { return std::max(a, b); }
Float clampTo(Float v, Float lo, Float hi) { return clamp(v, lo, hi); }
Spectrum minOf(const Spectrum& a, const Spectrum& b) {
  return {std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2])};
}
Spectrum maxOf(const Spectrum& a, const Spectrum& b) {
  return {std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2])};
}
Spectrum clampTo(const Spectrum& v, const Spectrum& lo, const Spectrum& hi) {
  return {clamp(v[0], lo[0], hi[0]), clamp(v[1], lo[1], hi[1]), clamp(v[2], lo[2], hi[2])};
}

// The draft's reconstruction filter: a sinc windowed by a wider sinc (Lanczos), on [-1, 1].
Float lanczos(Float x, Float tau) {
  x = std::abs(x);
  if (x < 1e-5f) return 1;
  if (x > 1) return 0;
  x *= kPi;
  return std::sin(x * tau) / (x * tau) * (std::sin(x) / x);
}

// Four consecutive source texels and their weights for one resampled texel (§11.5.2).
struct ResampleWeights {
  int first;
  Float weight[4];
};

std::vector<ResampleWeights> resampleWeights(int oldRes, int newRes) {
  std::vector<ResampleWeights> weights(static_cast<size_t>(newRes));
  constexpr Float kFilterWidth = 2;
  for (int i = 0; i < newRes; ++i) {
    ResampleWeights& w = weights[size_t(i)];
    // The new texel's centre in old continuous texel coordinates; the first old texel whose
    // centre (k + .5) is inside the filter's support.
    Float center = (Float(i) + 0.5f) * Float(oldRes) / Float(newRes);
    w.first = int(std::floor(center - kFilterWidth + 0.5f));
    Float sum = 0;
    for (int j = 0; j < 4; ++j) {
      Float pos = Float(w.first + j) + 0.5f;
      w.weight[j] = lanczos((pos - center) / kFilterWidth, 2);
      sum += w.weight[j];
    }
    for (Float& x : w.weight) x /= sum;  // so a constant image stays constant
  }
  return weights;
}

int wrapIndex(int i, int n, WrapMode wrap) {
  if (wrap == WrapMode::Repeat) {
    int r = i % n;
    return r < 0 ? r + n : r;
  }
  return clamp(i, 0, n - 1);  // "black" extends the edges here too (see mipmap.h)
}

// One separable pass over a row-major image whose rows are rowLength long: resamples each of its
// `lines` rows (alongRows) or columns from oldRes to newRes texels.
template <typename T>
std::vector<T> resampleAxis(const std::vector<T>& src, int oldRes, int newRes, int lines,
                            bool alongRows, int rowLength, WrapMode wrap) {
  std::vector<ResampleWeights> weights = resampleWeights(oldRes, newRes);
  int newRowLength = alongRows ? newRes : rowLength;
  std::vector<T> dst(size_t(newRes) * size_t(lines));
  for (int line = 0; line < lines; ++line)
    for (int i = 0; i < newRes; ++i) {
      const ResampleWeights& w = weights[size_t(i)];
      auto source = [&](int j) -> const T& {
        int k = wrapIndex(w.first + j, oldRes, wrap);
        return src[alongRows ? size_t(line) * size_t(rowLength) + size_t(k)
                             : size_t(k) * size_t(rowLength) + size_t(line)];
      };
      T sum(0), lo = source(0), hi = source(0);
      for (int j = 0; j < 4; ++j) {
        const T& v = source(j);
        sum += v * w.weight[j];
        lo = minOf(lo, v);
        hi = maxOf(hi, v);
      }
      size_t out = alongRows ? size_t(line) * size_t(newRowLength) + size_t(i)
                             : size_t(i) * size_t(newRowLength) + size_t(line);
      // Keep the negative lobes' ringing inside the range of the texels read.
      dst[out] = clampTo(sum, lo, hi);
    }
  return dst;
}

// The next level: the mean of each 2x2 block, or of the 2 texels of a block on a side that is
// already 1 texel long.
template <typename T>
std::vector<T> downsample(const std::vector<T>& src, int w, int h, int* newW, int* newH) {
  int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
  int sx = w > 1 ? 2 : 1, sy = h > 1 ? 2 : 1;
  Float inv = Float(1) / Float(sx * sy);
  std::vector<T> dst(size_t(nw) * size_t(nh));
  for (int y = 0; y < nh; ++y)
    for (int x = 0; x < nw; ++x) {
      T sum(0);
      for (int dy = 0; dy < sy; ++dy)
        for (int dx = 0; dx < sx; ++dx)
          sum += src[size_t(y * sy + dy) * size_t(w) + size_t(x * sx + dx)];
      dst[size_t(y) * size_t(nw) + size_t(x)] = sum * inv;
    }
  *newW = nw;
  *newH = nh;
  return dst;
}

}  // namespace

template <typename T>
MIPMap<T>::MIPMap(int width, int height, std::vector<T> texels, WrapMode wrap) : wrap_(wrap) {
  if (width < 1 || height < 1 || width > kMaxResolution || height > kMaxResolution)
    throw std::invalid_argument("MIP map: unsupported image size " + std::to_string(width) + "x" +
                                std::to_string(height));
  if (texels.size() != size_t(width) * size_t(height))
    throw std::invalid_argument("MIP map: texel count does not match the image size");
  if (!isPowerOf2(width)) {
    texels = resampleAxis(texels, width, roundUpPow2(width), height, true, width, wrap);
    width = roundUpPow2(width);
  }
  if (!isPowerOf2(height)) {
    texels = resampleAxis(texels, height, roundUpPow2(height), width, false, width, wrap);
    height = roundUpPow2(height);
  }
  levels_.push_back(Level{width, height, std::move(texels)});
  while (width > 1 || height > 1) {
    std::vector<T> next = downsample(levels_.back().texels, width, height, &width, &height);
    levels_.push_back(Level{width, height, std::move(next)});
  }
}

template <typename T>
T MIPMap<T>::texel(int level, int s, int t) const {
  const Level& l = levels_[size_t(level)];
  if (wrap_ == WrapMode::Black && (s < 0 || s >= l.width || t < 0 || t >= l.height)) return T(0);
  s = wrapIndex(s, l.width, wrap_);
  t = wrapIndex(t, l.height, wrap_);
  return l.texels[size_t(t) * size_t(l.width) + size_t(s)];
}

template <typename T>
T MIPMap<T>::lookupTrilinear(Point2f st, Float width) const {
  return mipmap_filter::trilinear(*this, st.x, st.y, width);
}

template <typename T>
T MIPMap<T>::lookupEWA(Point2f st, Vector2f dst0, Vector2f dst1, Float maxAnisotropy) const {
  return mipmap_filter::ewa(*this, st.x, st.y, dst0.x, dst0.y, dst1.x, dst1.y, maxAnisotropy);
}

template class MIPMap<Float>;
template class MIPMap<Spectrum>;

}  // namespace candela
