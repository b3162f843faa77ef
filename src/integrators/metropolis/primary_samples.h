// The state of a Metropolis chain in primary sample space (Kelemen et al. 2002; pbrt 3e
// §16.4.3): the uniform numbers a path is built from, mutated lazily. A number is touched only
// when the path asks for it, and then catches up on the mutations it missed: a large step
// (a fresh uniform) replaces it, and the small steps it missed are applied, wrapped into [0, 1):
// n Gaussian steps of sigma as one of sigma·√n (pbrt 3e), or Kelemen et al.'s exponentially
// distributed steps of 1/1024 to 1/64 one by one (pbrt 2e §15.7). Rejecting a proposal restores
// every number it touched.
//
// The numbers come in streams (camera subpath, light subpath, connection), each its own
// sequence, so that a path that reads more of one stream does not shift the others.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/rng.h"
#include "samplers/sampler.h"

namespace candela {

class PrimarySamples {
 public:
  static constexpr int kStreams = 3;
  enum class SmallStep { Gaussian, Exponential };
  PrimarySamples(uint64_t sequence, uint64_t seed, Float sigma, Float largeStepProbability,
                 SmallStep smallStep = SmallStep::Gaussian);
  // Where the random numbers of the mutations come from from now on.
  void reseed(uint64_t sequence, uint64_t seed) { rng_.setSequence(sequence, seed); }
  // A proposal: a large step with probability largeStepProbability, else a small step.
  void startIteration();
  // The first iteration of a chain: every number fresh (a large step without the coin flip).
  void startLargeStep();
  void accept();
  void reject();
  bool largeStep() const { return largeStep_; }
  Float get(int stream, int index);
  // A uniform for the chain's own decisions (acceptance), from the same generator.
  Float uniform() { return rng_.uniformFloat(); }

 private:
  struct Value {
    Float value = 0, backup = 0;
    int64_t lastModified = 0, backupModified = 0;
  };
  void bringUpToDate(Value& v);

  RNG rng_;
  Float sigma_, largeStepProbability_;
  SmallStep smallStep_;
  std::vector<Value> values_;
  int64_t iteration_ = 0, lastLargeStep_ = 0;
  bool largeStep_ = true;
  // The values a proposal touched, to restore on rejection.
  std::vector<int> touched_;
};

// A Sampler that reads one stream of a PrimarySamples, from its start after restart().
class PrimarySampleStream : public Sampler {
 public:
  PrimarySampleStream(PrimarySamples& samples, int stream) : samples_(samples), stream_(stream) {}
  void restart() { next_ = 0; }
  int samplesPerPixel() const override { return 1; }
  std::unique_ptr<Sampler> clone() const override {
    return std::make_unique<PrimarySampleStream>(samples_, stream_);
  }
  void startPixelSample(const Point2i&, int) override { restart(); }
  Float get1D() override { return samples_.get(stream_, next_++); }
  Point2f get2D() override {
    Float a = get1D();
    return Point2f(a, get1D());
  }
  Point2f getPixel2D() override { return get2D(); }

 private:
  PrimarySamples& samples_;
  int stream_;
  int next_ = 0;
};

}  // namespace candela
