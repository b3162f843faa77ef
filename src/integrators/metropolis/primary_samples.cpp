#include "integrators/metropolis/primary_samples.h"

#include <cmath>

namespace candela {

PrimarySamples::PrimarySamples(uint64_t sequence, uint64_t seed, Float sigma,
                               Float largeStepProbability, SmallStep smallStep)
    : rng_(sequence, seed),
      sigma_(sigma),
      largeStepProbability_(largeStepProbability),
      smallStep_(smallStep) {}

void PrimarySamples::startIteration() {
  ++iteration_;
  largeStep_ = rng_.uniformFloat() < largeStepProbability_;
  touched_.clear();
}

void PrimarySamples::startLargeStep() {
  ++iteration_;
  largeStep_ = true;
  touched_.clear();
}

void PrimarySamples::accept() {
  if (largeStep_) lastLargeStep_ = iteration_;
}

void PrimarySamples::reject() {
  for (int i : touched_) {
    Value& v = values_[size_t(i)];
    v.value = v.backup;
    v.lastModified = v.backupModified;
  }
  --iteration_;
}

Float PrimarySamples::get(int stream, int index) {
  size_t i = size_t(index) * kStreams + size_t(stream);
  if (i >= values_.size()) values_.resize(i + 1);
  Value& v = values_[i];
  if (v.lastModified < iteration_) {
    touched_.push_back(int(i));
    bringUpToDate(v);
  }
  return v.value;
}

void PrimarySamples::bringUpToDate(Value& v) {
  // A large step since the value was last touched replaced it with a fresh uniform.
  if (v.lastModified < lastLargeStep_) {
    v.value = rng_.uniformFloat();
    v.lastModified = lastLargeStep_;
  }
  // What the current state holds, restored if the proposal is rejected.
  v.backup = v.value;
  v.backupModified = v.lastModified;
  if (largeStep_) {
    v.value = rng_.uniformFloat();
  } else if (smallStep_ == SmallStep::Exponential) {
    // Kelemen et al.'s mutation: a step of size s2 exp(-ln(s2 / s1) u) between s1 = 1/1024 and
    // s2 = 1/64, up or down with equal probability (symmetric, so the acceptance ratio is the
    // ratio of the contributions); the missed steps one after another.
    constexpr Float s1 = Float(1) / 1024, s2 = Float(1) / 64;
    const Float logRatio = std::log(s2 / s1);
    Float x = v.value;
    for (int64_t k = v.lastModified; k < iteration_; ++k) {
      Float step = s2 * std::exp(-logRatio * rng_.uniformFloat());
      x += rng_.uniformFloat() < Float(0.5) ? step : -step;
      x -= std::floor(x);
    }
    v.value = std::min(x, kOneMinusEpsilon);
  } else {
    // The small steps it missed (the accepted ones and this one) add up to one Gaussian step
    // whose variance is their sum; Box-Muller for the normal deviate.
    int64_t missed = iteration_ - v.lastModified;
    Float u1 = std::max(rng_.uniformFloat(), Float(1e-7)), u2 = rng_.uniformFloat();
    Float normal = std::sqrt(-2 * std::log(u1)) * std::cos(2 * Float(M_PI) * u2);
    Float x = v.value + normal * sigma_ * std::sqrt(Float(missed));
    x -= std::floor(x);
    v.value = std::min(x, kOneMinusEpsilon);
  }
  v.lastModified = iteration_;
}

}  // namespace candela
