// pbrt-v3's named media as the build resolves them: MediumInterface names -> the media of the
// MakeNamedMedium statements, created once each and only when something names them; interfaces
// shared between the shapes that have the same pair. Owns what it creates (the RenderJob keeps
// it alive).
#pragma once

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "media/medium_interface.h"
#include "parser/scene_description.h"

namespace candela {

class NamedMedia {
 public:
  explicit NamedMedia(const SceneDescription& desc) : desc_(desc) {}
  // The medium called name; null for "" (vacuum). An unknown name is a SceneError at loc (the
  // MediumInterface statement).
  const Medium* get(const std::string& name, const FileLoc& loc);
  // The interface of a shape; null when its two sides are the same medium (no transition).
  const MediumInterface* interfaceOf(const ShapeDesc& shape);
  // Whether anything named a medium, and the MakeNamedMedium statement of the first one named.
  bool used() const { return firstUsed_ != nullptr; }
  const MediumDesc* firstUsed() const { return firstUsed_; }
  FileLoc firstReferenceLoc() const { return firstReference_; }
  const SceneDescription& description() const { return desc_; }
  long createdCount() const { return long(created_.size()); }
  long interfaceCount() const { return long(interfaceStorage_.size()); }
  // The MakeNamedMedium statements nothing named.
  std::vector<const MediumDesc*> unused() const;

 private:
  const SceneDescription& desc_;
  std::map<std::string, std::unique_ptr<Medium>> created_;
  std::map<std::pair<const Medium*, const Medium*>, const MediumInterface*> interfaces_;
  std::deque<MediumInterface> interfaceStorage_;
  const MediumDesc* firstUsed_ = nullptr;
  FileLoc firstReference_;
};

}  // namespace candela
