#include "assembly/named_media.h"

#include "assembly/named_medium_factory.h"
#include "core/error.h"

namespace candela {

const Medium* NamedMedia::get(const std::string& name, const FileLoc& loc) {
  if (name.empty()) return nullptr;
  if (auto it = created_.find(name); it != created_.end()) return it->second.get();
  const MediumDesc* desc = nullptr;
  for (const MediumDesc& m : desc_.media)
    if (m.mediumName == name) desc = &m;
  if (!desc)
    throw SceneError(
        loc, "MediumInterface names unknown medium '" + name + "' (no MakeNamedMedium defines it)");
  std::unique_ptr<Medium> medium = createNamedMedium(*desc);
  if (!firstUsed_) {
    firstUsed_ = desc;
    firstReference_ = loc;
  }
  return (created_[name] = std::move(medium)).get();
}

const MediumInterface* NamedMedia::interfaceOf(const ShapeDesc& shape) {
  if (shape.insideMedium.empty() && shape.outsideMedium.empty()) return nullptr;
  const Medium* inside = get(shape.insideMedium, shape.mediumLoc);
  const Medium* outside = get(shape.outsideMedium, shape.mediumLoc);
  if (inside == outside) return nullptr;
  auto [it, isNew] = interfaces_.try_emplace({inside, outside}, nullptr);
  if (isNew) {
    interfaceStorage_.push_back(MediumInterface{inside, outside});
    it->second = &interfaceStorage_.back();
  }
  return it->second;
}

std::vector<const MediumDesc*> NamedMedia::unused() const {
  std::vector<const MediumDesc*> r;
  for (const MediumDesc& m : desc_.media)
    if (!created_.count(m.mediumName)) r.push_back(&m);
  return r;
}

}  // namespace candela
