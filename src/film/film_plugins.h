// The films' table (issue 34: one home per plug-in): the film's name, dialects, parameters and
// create function. createFilm dispatches through it, and unknown-name errors, `candela
// --list-plugins` and `candela --describe` read it.
#pragma once

#include <memory>
#include <optional>
#include <span>

#include "core/plugin_spec.h"
#include "film/film.h"

namespace candela {

// What every film is made from: its parameters, the pixel filter (null is an error), and the
// command line's crop window that replaces the scene's. Bad values are SceneErrors at the
// parameter or loc.
using FilmCreate = std::unique_ptr<Film> (*)(const ParamSet& params, std::unique_ptr<Filter> filter,
                                             const FileLoc& loc,
                                             std::optional<Bounds2f> cropOverride);

struct FilmPlugin {
  PluginSpec spec;
  FilmCreate create;
};

std::span<const FilmPlugin> filmPlugins();

}  // namespace candela
