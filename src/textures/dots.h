// Random polka dots (lrt draft §11.7.2): (s, t) space is cut into unit cells centred on integer
// points; a cell holds a dot when noise at its centre (offset by .5 from the lattice, where noise
// is zero) is positive; the dot has radius .35 and its centre is moved by up to .15 by two more
// noise lookups. Not antialiased (the draft leaves that to exercise 11.10).
#pragma once

#include <memory>

#include "textures/mapping.h"
#include "textures/noise.h"
#include "textures/texture.h"

namespace candela {

// True if (s, t) lies inside a dot.
inline bool insidePolkaDot(Float s, Float t) {
  if (!std::isfinite(s) || !std::isfinite(t)) return false;
  Float sCell = std::floor(s + Float(0.5)), tCell = std::floor(t + Float(0.5));
  if (noise(sCell + Float(0.5), tCell + Float(0.5)) <= 0) return false;
  constexpr Float kRadius = 0.35f, kMaxShift = 0.5f - kRadius;
  Float sCenter = sCell + kMaxShift * noise(sCell + 1.5f, tCell + 2.8f);
  Float tCenter = tCell + kMaxShift * noise(sCell + 4.5f, tCell + 9.8f);
  Float ds = s - sCenter, dt = t - tCenter;
  return ds * ds + dt * dt < kRadius * kRadius;
}

template <typename T>
class DotsTexture : public Texture<T> {
 public:
  DotsTexture(std::unique_ptr<TextureMapping2D> mapping, const Texture<T>* outside,
              const Texture<T>* inside)
      : mapping_(std::move(mapping)), outside_(outside), inside_(inside) {}
  T evaluate(const SurfaceInteraction& si) const override {
    Point2f st = mapping_->map(si).st;
    return (insidePolkaDot(st.x, st.y) ? inside_ : outside_)->evaluate(si);
  }

 private:
  std::unique_ptr<TextureMapping2D> mapping_;
  const Texture<T>* outside_;
  const Texture<T>* inside_;
};

}  // namespace candela
