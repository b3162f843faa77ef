// Names whose definitions are part of the graphics state (pbrt 3e App. B: named textures and named
// materials), so AttributeBegin saves them and AttributeEnd restores them. A statement sees the
// definitions in effect where it is written. Restoring undoes a log of the definitions made since
// the mark, so saving costs nothing however many names exist.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace candela {

class ScopedNames {
 public:
  struct Definition {
    int index;  // into the description's list of definitions
    int depth;  // the attribute nesting it was made at
  };

  // Defines name as index at nesting depth; returns the definition it replaces when that one was
  // made in the same attribute block (shadowing an outer one is the normal scoped case).
  std::optional<Definition> define(const std::string& name, int index, int depth) {
    auto it = current_.find(name);
    std::optional<Definition> previous;
    if (it != current_.end()) previous = it->second;
    log_.push_back({name, previous});
    current_[name] = {index, depth};
    if (previous && previous->depth == depth) return previous;
    return std::nullopt;
  }

  const Definition* find(const std::string& name) const {
    auto it = current_.find(name);
    return it == current_.end() ? nullptr : &it->second;
  }

  size_t mark() const { return log_.size(); }

  // Undoes every definition made since mark, newest first.
  void restore(size_t mark) {
    while (log_.size() > mark) {
      const Undo& u = log_.back();
      if (u.previous)
        current_[u.name] = *u.previous;
      else
        current_.erase(u.name);
      log_.pop_back();
    }
  }

  const std::map<std::string, Definition>& current() const { return current_; }

  void clear() {
    current_.clear();
    log_.clear();
  }

 private:
  struct Undo {
    std::string name;
    std::optional<Definition> previous;
  };
  std::map<std::string, Definition> current_;
  std::vector<Undo> log_;
};

}  // namespace candela
