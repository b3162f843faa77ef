// What a plug-in is, as its kind's table declares it: name, the dialects that have it, one line
// of what it does, and every parameter it reads with type, default, rule and dialect. The tables
// (one per kind, beside the classes: shapes/shape_plugins.cpp, materials/material_plugins.cpp,
// ...) are the only list of names: unknown-name errors, `candela --list-plugins` and
// `candela --describe` read them, and tests/unit/test_plugin_tables.cpp checks each declaration
// against what the plug-in's create function really reads.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace candela {

// The dialects a plug-in or a parameter belongs to.
enum DialectMask : unsigned {
  kLrt = 1u,      // the lrt draft's scene format
  kPbrtV2 = 2u,   // pbrt-v1/v2 (pbrt 2e)
  kPbrtV3 = 4u,   // pbrt-v3 (pbrt 3e)
  kCandela = 8u,  // candela's own extension, in any dialect
  kAllDialects = kLrt | kPbrtV2 | kPbrtV3,
  kPbrt = kPbrtV2 | kPbrtV3,
};

struct ParamSpec {
  std::string_view name;
  // As written in a scene file: "float", "integer", "bool", "string", "spectrum", "point3",
  // "vector3", "normal3", "point2"; "float texture" / "spectrum texture" for a texture name or a
  // constant; a trailing "[]" for a list.
  std::string_view type;
  // The value when absent, in scene syntax ("0.5", "1 1 1", "true", "gaussian"); text in
  // parentheses when it is not a constant: "(required)", "(the frame's aspect)", "(none)".
  std::string_view defaultValue;
  // Where pbrt-v3's default differs from pbrt-v2's and lrt's: pbrt-v3's; empty when the same.
  std::string_view pbrtV3Default;
  // What a value must be, as ValueRange::describe() or ParamSet's one-of rule words it
  // ("positive and finite", "at least 1", "within [0, 1]", "one of box, gaussian"); empty: any.
  std::string_view rule;
  unsigned dialects = kAllDialects;
  std::string_view meaning;
  // When the plug-in reads the parameter only in some cases, which ("with \"mapping\" planar");
  // empty: always.
  std::string_view onlyWhen = {};
};

struct PluginSpec {
  std::string_view kind;  // "shape", "material", ... as errors and --list-plugins name it
  std::string_view name;
  unsigned dialects = kAllDialects;
  std::string_view summary;  // one line, with the book section it follows
  std::span<const ParamSpec> params;
};

// Parameter lists shared by several plug-ins (a texture mapping's, say) joined with each one's own:
// constexpr auto kParams = joinParams(kMappingParams, std::to_array<ParamSpec>({...}));
template <size_t A, size_t B>
constexpr std::array<ParamSpec, A + B> joinParams(const std::array<ParamSpec, A>& a,
                                                  const std::array<ParamSpec, B>& b) {
  std::array<ParamSpec, A + B> out{};
  for (size_t i = 0; i < A; ++i) out[i] = a[i];
  for (size_t i = 0; i < B; ++i) out[A + i] = b[i];
  return out;
}

// "lrt, pbrt-v2, pbrt-v3", "pbrt-v3", "candela".
std::string dialectNames(unsigned mask);

// The entry called name in a kind's table (any type with a `spec` member), or nullptr.
template <class Entry>
const Entry* findPlugin(std::span<const Entry> table, std::string_view name) {
  for (const Entry& e : table)
    if (e.spec.name == name) return &e;
  return nullptr;
}

// The names of a table, in its order.
template <class Entry>
std::vector<std::string_view> pluginNames(std::span<const Entry> table) {
  std::vector<std::string_view> names;
  for (const Entry& e : table) names.push_back(e.spec.name);
  return names;
}

// "unknown shape 'sphear' (known: sphere, cylinder, ...)" at loc.
[[noreturn]] void throwUnknownPlugin(const FileLoc& loc, std::string_view kind,
                                     const std::string& name,
                                     const std::vector<std::string_view>& known);

// The entry called name, or the unknown-name error listing the table's names.
template <class Entry>
const Entry& requirePlugin(std::span<const Entry> table, std::string_view kind,
                           const std::string& name, const FileLoc& loc) {
  if (const Entry* e = findPlugin(table, name)) return *e;
  throwUnknownPlugin(loc, kind, name, pluginNames(table));
}

// What `candela --describe` prints: the summary, the dialects, one line per parameter.
std::string describePlugin(const PluginSpec& spec);

}  // namespace candela
