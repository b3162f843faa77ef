// Test helper: scene parameters as the parser hands them to the factories, e.g. "float radius" [2]
// written at scene.pbrt:7:3. Each builder sets the type's pbrt spelling, which error messages and
// unused-parameter warnings quote; the location defaults to FileLoc{} and is passed where a test
// checks it.
#pragma once

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "core/paramset.h"

namespace candela::test {

// An item without values, for the builders below.
inline ParamItem paramItem(ParamType type, std::string typeName, std::string name, FileLoc loc) {
  ParamItem item;
  item.type = type;
  item.typeName = std::move(typeName);
  item.name = std::move(name);
  item.loc = std::move(loc);
  return item;
}

// Numbers and tuples of numbers, flattened as ParamItem stores them.
inline ParamItem floatValues(ParamType type, std::string typeName, std::string name,
                             std::vector<Float> values, FileLoc loc) {
  ParamItem item = paramItem(type, std::move(typeName), std::move(name), std::move(loc));
  item.floats = std::move(values);
  return item;
}

inline ParamItem floats(std::string name, std::vector<Float> values, FileLoc loc = {}) {
  return floatValues(ParamType::Float, "float", std::move(name), std::move(values), std::move(loc));
}
inline ParamItem point2s(std::string name, std::vector<Float> values, FileLoc loc = {}) {
  return floatValues(ParamType::Point2, "point2", std::move(name), std::move(values),
                     std::move(loc));
}
inline ParamItem points(std::string name, std::vector<Float> values, FileLoc loc = {}) {
  return floatValues(ParamType::Point3, "point3", std::move(name), std::move(values),
                     std::move(loc));
}
inline ParamItem vectors(std::string name, std::vector<Float> values, FileLoc loc = {}) {
  return floatValues(ParamType::Vector3, "vector3", std::move(name), std::move(values),
                     std::move(loc));
}
inline ParamItem normals(std::string name, std::vector<Float> values, FileLoc loc = {}) {
  return floatValues(ParamType::Normal3, "normal", std::move(name), std::move(values),
                     std::move(loc));
}
// RGB triples.
inline ParamItem rgb(std::string name, std::vector<Float> values, FileLoc loc = {}) {
  return floatValues(ParamType::Spectrum, "rgb", std::move(name), std::move(values),
                     std::move(loc));
}

inline ParamItem ints(std::string name, std::vector<int> values, FileLoc loc = {}) {
  ParamItem item = paramItem(ParamType::Integer, "integer", std::move(name), std::move(loc));
  item.ints = std::move(values);
  return item;
}

inline ParamItem bools(std::string name, std::vector<bool> values, FileLoc loc = {}) {
  ParamItem item = paramItem(ParamType::Bool, "bool", std::move(name), std::move(loc));
  item.bools = std::move(values);
  return item;
}

inline ParamItem strings(std::string name, std::vector<std::string> values, FileLoc loc = {}) {
  ParamItem item = paramItem(ParamType::String, "string", std::move(name), std::move(loc));
  item.strings = std::move(values);
  return item;
}

// A reference to the named texture: "texture Kd" "checks".
inline ParamItem texture(std::string name, std::string textureName, FileLoc loc = {}) {
  ParamItem item = paramItem(ParamType::Texture, "texture", std::move(name), std::move(loc));
  item.strings = {std::move(textureName)};
  return item;
}

inline ParamSet paramSet(std::initializer_list<ParamItem> items) {
  ParamSet ps;
  for (const ParamItem& item : items) ps.add(item);
  return ps;
}

}  // namespace candela::test
