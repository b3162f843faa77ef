#include "app/scene_hash.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "core/rng.h"

namespace candela {

void SceneHash::add(std::string_view text) {
  auto mix = [this](uint64_t v) {
    h_ = mixBits(h_ ^ (v + 0x9e3779b97f4a7c15ULL + (h_ << 6) + (h_ >> 2)));
  };
  mix(text.size());
  size_t i = 0;
  for (; i + 8 <= text.size(); i += 8) {
    uint64_t word;
    std::memcpy(&word, text.data() + i, 8);
    mix(word);
  }
  uint64_t tail = 0;
  std::memcpy(&tail, text.data() + i, text.size() - i);
  mix(tail);
}

void SceneHash::addFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open the scene file again to hash it");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw FileError(path, "cannot read the scene file again to hash it");
  add(text);
}

std::string SceneHash::hex() const {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h_);
  return buf;
}

std::string imageOptionsText(const CliOptions& cli, bool half) {
  std::string s;
  auto add = [&s](const char* name, const std::string& value) {
    s.append(s.empty() ? "" : " ").append(name).append("=").append(value);
  };
  add("quick", cli.quick ? "1" : "0");
  add("accel", cli.accelerator);
  add("subdiv", cli.subdiv);
  add("dialect", cli.dialect);
  add("coat-fresnel", cli.coatFresnel);
  add("hyperboloid-normal", cli.hyperboloidNormal);
  add("turbulence", cli.turbulence);
  add("colorspace", cli.colorSpace);
  add("aov", cli.aovs);
  add("half", half ? "1" : "0");
  // Only when set, so that pieces rendered before the option existed still merge.
  if (!cli.lightSampler.empty()) add("light-sampler", cli.lightSampler);
  if (cli.guiding) add("guiding", "1");
  if (cli.noiseThreshold > 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g/%d", cli.noiseThreshold, cli.adaptiveMinSamples);
    add("noise-threshold", buf);
  }
  return s;
}

}  // namespace candela
