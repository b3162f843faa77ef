#include "parser/parser.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/read_file.h"
#include "parser/spectrum_input.h"
#include "parser/tokenizer.h"

namespace candela {

namespace {

namespace fs = std::filesystem;

// Deeper Include chains than this are surely a mistake (cycles are caught separately), and so
// are more Includes in one parse than this (files including each other many times over).
constexpr int kMaxIncludeDepth = 64;
constexpr int kMaxIncludes = 100000;

enum class Directive {
  Accelerator,
  ActiveTransform,
  AreaLightSource,
  AttributeBegin,
  AttributeEnd,
  BumpMap,
  Camera,
  ConcatTransform,
  CoordinateSystem,
  CoordSysTransform,
  Film,
  Identity,
  Import,
  Include,
  Integrator,
  LightSource,
  LookAt,
  MakeNamedMaterial,
  MakeNamedMedium,
  Material,
  MediumInterface,
  NamedMaterial,
  ObjectBegin,
  ObjectEnd,
  ObjectInstance,
  Option,
  PixelFilter,
  Renderer,
  ReverseOrientation,
  Rotate,
  Sampler,
  Scale,
  SearchPath,
  Shape,
  SurfaceIntegrator,
  Texture,
  ToneMap,
  Transform,
  TransformBegin,
  TransformEnd,
  TransformTimes,
  Translate,
  Volume,
  VolumeIntegrator,
  WorldBegin,
  WorldEnd
};

const std::unordered_map<std::string_view, Directive>& directives() {
  using D = Directive;
  static const std::unordered_map<std::string_view, Directive> table = {
      {"Accelerator", D::Accelerator},
      {"ActiveTransform", D::ActiveTransform},
      {"AreaLightSource", D::AreaLightSource},
      {"AttributeBegin", D::AttributeBegin},
      {"AttributeEnd", D::AttributeEnd},
      {"BumpMap", D::BumpMap},
      {"Camera", D::Camera},
      {"ConcatTransform", D::ConcatTransform},
      {"CoordinateSystem", D::CoordinateSystem},
      {"CoordSysTransform", D::CoordSysTransform},
      {"Film", D::Film},
      {"Identity", D::Identity},
      {"Import", D::Import},
      {"Include", D::Include},
      {"Integrator", D::Integrator},
      {"LightSource", D::LightSource},
      {"LookAt", D::LookAt},
      {"MakeNamedMaterial", D::MakeNamedMaterial},
      {"MakeNamedMedium", D::MakeNamedMedium},
      {"Material", D::Material},
      {"MediumInterface", D::MediumInterface},
      {"NamedMaterial", D::NamedMaterial},
      {"ObjectBegin", D::ObjectBegin},
      {"ObjectEnd", D::ObjectEnd},
      {"ObjectInstance", D::ObjectInstance},
      {"Option", D::Option},
      {"PixelFilter", D::PixelFilter},
      {"Renderer", D::Renderer},
      {"ReverseOrientation", D::ReverseOrientation},
      {"Rotate", D::Rotate},
      {"Sampler", D::Sampler},
      {"Scale", D::Scale},
      {"SearchPath", D::SearchPath},
      {"Shape", D::Shape},
      {"SurfaceIntegrator", D::SurfaceIntegrator},
      {"Texture", D::Texture},
      {"ToneMap", D::ToneMap},
      {"Transform", D::Transform},
      {"TransformBegin", D::TransformBegin},
      {"TransformEnd", D::TransformEnd},
      {"TransformTimes", D::TransformTimes},
      {"Translate", D::Translate},
      {"Volume", D::Volume},
      {"VolumeIntegrator", D::VolumeIntegrator},
      {"WorldBegin", D::WorldBegin},
      {"WorldEnd", D::WorldEnd},
  };
  return table;
}

// A path written in a file, taken relative to that file's directory.
std::string resolveRelative(const std::string& written, const std::string& referringFile) {
  fs::path p(written);
  if (p.is_absolute() || referringFile == "-") return written;
  return (fs::path(referringFile).parent_path() / p).lexically_normal().string();
}

std::string canonicalKey(const std::string& path) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(path, ec);
  return ec ? fs::absolute(path, ec).lexically_normal().string() : c.string();
}

// The values of one parameter, with where they were written.
struct RawValues {
  std::vector<Token> tokens;
  FileLoc declLoc;
};

class Parser {
 public:
  Parser(ParserTarget& target, const WarningCallback& warn, const SceneFileReader& readFile)
      : target_(target), warn_(warn), readFile_(readFile) {}

  void parseText(const std::string& text, const std::string& filename) {
    std::string key = filename == "-" ? std::string("-") : fileKey(filename);
    includeStack_.push_back(key);
    Tokenizer tok(text, filename);
    while (statement(tok)) {
    }
    includeStack_.pop_back();
  }

 private:
  void warn(const FileLoc& loc, const std::string& msg) {
    if (warn_)
      warn_(loc, msg);
    else
      std::cerr << loc.str() << ": warning: " << msg << "\n";
  }

  // Parses one statement; false at the end of the text.
  bool statement(Tokenizer& tok) {
    Token t = tok.next();
    if (t.kind == TokenKind::End) return false;
    if (t.kind != TokenKind::Word)
      throw SceneError(t.loc, "expected a directive, found " + describeToken(t));
    auto it = directives().find(t.text);
    if (it == directives().end())
      throw SceneError(t.loc, "unknown directive '" + printable(t.text) + "'");
    dispatch(it->second, t, tok);
    return true;
  }

  std::string quoted(Tokenizer& tok, const Token& directive, const char* what) {
    Token t = tok.next();
    if (t.kind != TokenKind::String)
      throw SceneError(t.loc, "'" + directive.text + "' needs " + what +
                                  " as a quoted string, found " + describeToken(t));
    return t.text;
  }

  // n numbers, optionally enclosed in [ ] (pbrt writes "Transform [ ... ]", lrt bare numbers).
  std::vector<Float> numbers(Tokenizer& tok, const Token& directive, size_t n) {
    std::vector<Float> v;
    bool bracketed = tok.peek().kind == TokenKind::OpenBracket;
    if (bracketed) tok.next();
    while (bracketed ? tok.peek().kind != TokenKind::CloseBracket : v.size() < n) {
      Token t = tok.next();
      if (t.kind != TokenKind::Number)
        throw SceneError(t.loc, "'" + directive.text + "' needs " + std::to_string(n) +
                                    " numbers, found " + describeToken(t));
      v.push_back(Float(t.number));
    }
    if (bracketed) {
      Token close = tok.next();
      if (v.size() != n)
        throw SceneError(close.loc, "'" + directive.text + "' needs " + std::to_string(n) +
                                        " numbers, found " + std::to_string(v.size()));
    }
    return v;
  }

  void include(Tokenizer& tok, const Token& directive) {
    Token nameTok = tok.peek();
    std::string written = quoted(tok, directive, "a file name");
    std::string path = resolveRelative(written, tok.filename());
    std::string key = fileKey(path);
    for (const std::string& open : includeStack_)
      if (open == key)
        throw SceneError(nameTok.loc, "include cycle: '" + printable(written, 200) +
                                          "' is already being parsed");
    if (++includeCount_ > kMaxIncludes)
      throw SceneError(nameTok.loc, "more than " + std::to_string(kMaxIncludes) +
                                        " Include statements in one parse");
    if (int(includeStack_.size()) > kMaxIncludeDepth)
      throw SceneError(nameTok.loc, "Include nested more than " + std::to_string(kMaxIncludeDepth) +
                                        " files deep");
    std::string text;
    try {
      text = read(path);
    } catch (const FileError& e) {
      throw SceneError(nameTok.loc, "cannot read included file: " + std::string(e.what()));
    }
    includeStack_.push_back(key);
    Tokenizer inner(std::move(text), path);
    while (statement(inner)) {
    }
    includeStack_.pop_back();
  }

  // The contents of a file the scene names, through the caller's reader when there is one.
  std::string read(const std::string& path) const {
    return readFile_ ? readFile_(path) : readWholeFile(path);
  }
  // What identifies a file in the include stack: its canonical path on the filesystem; files of
  // a caller's reader are named by their lexically normal path (the filesystem is not asked).
  std::string fileKey(const std::string& path) const {
    return readFile_ ? fs::path(path).lexically_normal().string() : canonicalKey(path);
  }

  ParamSet params(Tokenizer& tok);
  void parameter(Tokenizer& tok, ParamSet& ps);
  void dispatch(Directive d, const Token& t, Tokenizer& tok);

  ParserTarget& target_;
  const WarningCallback& warn_;
  const SceneFileReader& readFile_;
  std::vector<std::string> includeStack_;  // canonical paths of the files being parsed
  int includeCount_ = 0;
};

// ---- Parameter lists: "type name" value | "type name" [ values ] --------------------------------

struct TypeInfo {
  ParamType type;
  int tuple;  // numbers per value for number-backed types
};

bool lookupType(const std::string& t, TypeInfo* info) {
  static const std::unordered_map<std::string_view, TypeInfo> types = {
      {"integer", {ParamType::Integer, 1}},    {"float", {ParamType::Float, 1}},
      {"point2", {ParamType::Point2, 2}},      {"vector2", {ParamType::Vector2, 2}},
      {"point", {ParamType::Point3, 3}},       {"point3", {ParamType::Point3, 3}},
      {"vector", {ParamType::Vector3, 3}},     {"vector3", {ParamType::Vector3, 3}},
      {"normal", {ParamType::Normal3, 3}},     {"normal3", {ParamType::Normal3, 3}},
      {"color", {ParamType::Spectrum, 3}},     {"rgb", {ParamType::Spectrum, 3}},
      {"xyz", {ParamType::Spectrum, 3}},       {"spectrum", {ParamType::Spectrum, 2}},
      {"blackbody", {ParamType::Spectrum, 1}}, {"bool", {ParamType::Bool, 1}},
      {"string", {ParamType::String, 1}},      {"texture", {ParamType::Texture, 1}},
  };
  auto it = types.find(t);
  if (it == types.end()) return false;
  *info = it->second;
  return true;
}

std::vector<std::string> splitWords(const std::string& s) {
  std::vector<std::string> words;
  std::istringstream in(s);
  std::string w;
  while (in >> w) words.push_back(w);
  return words;
}

ParamSet Parser::params(Tokenizer& tok) {
  ParamSet ps;
  while (tok.peek().kind == TokenKind::String) parameter(tok, ps);
  return ps;
}

void Parser::parameter(Tokenizer& tok, ParamSet& ps) {
  Token decl = tok.next();
  // "type name", optionally with lrt's variability ("uniform"/"varying"/"vertex") in front and
  // an array size after the name ("float cropwindow[4]").
  std::vector<std::string> words = splitWords(decl.text);
  if (words.size() == 3 && (words[0] == "uniform" || words[0] == "varying" || words[0] == "vertex"))
    words.erase(words.begin());
  if (words.size() != 2)
    throw SceneError(
        decl.loc, "expected a parameter declaration \"type name\", found " + describeToken(decl));
  std::string typeName = words[0], name = words[1];
  if (size_t bracket = name.find('[');
      bracket != std::string::npos && bracket > 0 && name.back() == ']')
    name.resize(bracket);
  TypeInfo info{};
  if (!lookupType(typeName, &info))
    throw SceneError(
        decl.loc, "unknown parameter type '" + printable(typeName) + "' in " + describeToken(decl));
  std::string what = "parameter \"" + printable(typeName) + " " + printable(name) + "\"";

  // The values: one bare value or a bracketed list.
  std::vector<Token> values;
  if (tok.peek().kind == TokenKind::OpenBracket) {
    Token open = tok.next();
    while (true) {
      Token v = tok.next();
      if (v.kind == TokenKind::CloseBracket) break;
      if (v.kind == TokenKind::End)
        throw SceneError(open.loc, "'[' of " + what + " is never closed");
      if (v.kind == TokenKind::OpenBracket)
        throw SceneError(v.loc, "unexpected '[' inside the values of " + what);
      values.push_back(std::move(v));
    }
  } else {
    Token v = tok.next();
    if (v.kind != TokenKind::Number && v.kind != TokenKind::String && v.kind != TokenKind::Word)
      throw SceneError(v.loc, "expected a value for " + what + ", found " + describeToken(v));
    values.push_back(std::move(v));
  }

  ParamItem item;
  item.type = info.type;
  item.name = name;
  item.typeName = typeName;
  item.loc = decl.loc;

  auto expectNumber = [&](const Token& v) {
    if (v.kind != TokenKind::Number)
      throw SceneError(v.loc, what + " expects numbers, found " + describeToken(v));
    return v.number;
  };
  auto expectString = [&](const Token& v) -> const std::string& {
    if (v.kind != TokenKind::String)
      throw SceneError(v.loc, what + " expects quoted strings, found " + describeToken(v));
    return v.text;
  };
  auto needMultiple = [&](size_t n, int k) {
    if (n % k != 0)
      throw SceneError(decl.loc, what + " needs a multiple of " + std::to_string(k) +
                                     " numbers, found " + std::to_string(n));
  };
  SpectrumUse use = spectrumUseForParameter(name);
  // Spectral values near float's limit can give a colour beyond it (a constant 3.3e38 spectrum
  // is white beyond 3.4e38), which would be infinite in every later computation.
  auto addColour = [&](const Spectrum& s, const FileLoc& loc) {
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(s[c]))
        throw SceneError(loc, what + " gives a colour beyond the float range");
    item.floats.insert(item.floats.end(), {s[0], s[1], s[2]});
  };

  switch (info.type) {
    case ParamType::Integer:
      for (const Token& v : values) {
        double d = expectNumber(v);
        if (d != std::floor(d) || std::abs(d) > 2147483647.0)
          throw SceneError(v.loc, what + " expects integers, found " + describeToken(v));
        item.ints.push_back(int(d));
      }
      break;
    case ParamType::Bool:
      for (const Token& v : values) {
        // pbrt-v2/v3 write "true" quoted; some files write it bare.
        if ((v.kind != TokenKind::String && v.kind != TokenKind::Word) ||
            (v.text != "true" && v.text != "false"))
          throw SceneError(v.loc, what + " expects true or false, found " + describeToken(v));
        item.bools.push_back(v.text == "true");
      }
      break;
    case ParamType::String:
    case ParamType::Texture:
      for (const Token& v : values) item.strings.push_back(expectString(v));
      break;
    case ParamType::Spectrum:
      if (typeName == "color" || typeName == "rgb") {
        for (const Token& v : values) item.floats.push_back(Float(expectNumber(v)));
        needMultiple(item.floats.size(), 3);
      } else if (typeName == "xyz") {
        std::vector<Float> f;
        for (const Token& v : values) f.push_back(Float(expectNumber(v)));
        needMultiple(f.size(), 3);
        for (size_t i = 0; i < f.size(); i += 3) {
          addColour(Spectrum::fromXYZ(f[i], f[i + 1], f[i + 2]), values[i].loc);
        }
      } else if (typeName == "blackbody") {
        // pbrt-v2: pairs (temperature K, scale); pbrt-v3: one temperature.
        std::vector<Float> f;
        for (const Token& v : values) f.push_back(Float(expectNumber(v)));
        if (f.size() != 1 && f.size() % 2 != 0)
          throw SceneError(decl.loc, what +
                                         " needs one temperature or (temperature, scale) "
                                         "pairs, found " +
                                         std::to_string(f.size()) + " numbers");
        if (f.size() == 1) f.push_back(1);
        for (size_t i = 0; i < f.size(); i += 2) {
          if (!(f[i] > 0))
            throw SceneError(values[i].loc, what + " needs a temperature above 0 K, found " +
                                                describeToken(values[i]));
          addColour(blackbodyToRGB(f[i], f[i + 1]), values[i].loc);
        }
      } else if (!values.empty() && values[0].kind == TokenKind::String) {
        // "spectrum" "file.spd": one spectrum per file.
        for (const Token& v : values) {
          std::string path = resolveRelative(expectString(v), tok.filename());
          std::vector<SpectrumSample> samples;
          try {
            samples = parseSpectrumFile(read(path), path);
          } catch (const FileError& e) {
            throw SceneError(v.loc, "cannot read spectrum of " + what + ": " + e.what());
          }
          addColour(spectrumSamplesToRGB(std::move(samples), use), v.loc);
        }
      } else if (!values.empty()) {
        // "spectrum" [ λ v λ v ... ]: one spectrum.
        std::vector<SpectrumSample> samples;
        for (size_t i = 0; i < values.size(); ++i) expectNumber(values[i]);
        if (values.size() % 2 != 0)
          throw SceneError(decl.loc, what + " needs (wavelength, value) pairs, found " +
                                         std::to_string(values.size()) + " numbers");
        for (size_t i = 0; i < values.size(); i += 2)
          samples.push_back({Float(values[i].number), Float(values[i + 1].number)});
        addColour(spectrumSamplesToRGB(std::move(samples), use), values[0].loc);
      }
      break;
    default:  // Float, Point*, Vector*, Normal3
      for (const Token& v : values) item.floats.push_back(Float(expectNumber(v)));
      needMultiple(item.floats.size(), info.tuple);
      break;
  }
  ps.add(std::move(item));
}

// ---- Statements -------------------------------------------------------------------------------

void Parser::dispatch(Directive d, const Token& t, Tokenizer& tok) {
  using D = Directive;
  const FileLoc& loc = t.loc;
  auto named = [&](auto method) {
    std::string name = quoted(tok, t, "a name");
    ParamSet ps = params(tok);
    (target_.*method)(name, std::move(ps), loc);
  };
  switch (d) {
    case D::Accelerator:
      named(&ParserTarget::accelerator);
      break;
    case D::AreaLightSource:
      named(&ParserTarget::areaLightSource);
      break;
    case D::BumpMap:
      named(&ParserTarget::bumpMap);
      break;
    case D::Camera:
      named(&ParserTarget::camera);
      break;
    case D::Film:
      named(&ParserTarget::film);
      break;
    case D::Integrator:
      named(&ParserTarget::integrator);
      break;
    case D::LightSource:
      named(&ParserTarget::lightSource);
      break;
    case D::MakeNamedMaterial:
      named(&ParserTarget::makeNamedMaterial);
      break;
    case D::MakeNamedMedium:
      named(&ParserTarget::makeNamedMedium);
      break;
    case D::Material:
      named(&ParserTarget::material);
      break;
    case D::PixelFilter:
      named(&ParserTarget::pixelFilter);
      break;
    case D::Renderer:
      named(&ParserTarget::renderer);
      break;
    case D::Sampler:
      named(&ParserTarget::sampler);
      break;
    case D::Shape:
      named(&ParserTarget::shape);
      break;
    case D::SurfaceIntegrator:
      named(&ParserTarget::surfaceIntegrator);
      break;
    case D::ToneMap:
      named(&ParserTarget::toneMap);
      break;
    case D::Volume:
      named(&ParserTarget::volume);
      break;
    case D::VolumeIntegrator:
      named(&ParserTarget::volumeIntegrator);
      break;

    case D::ActiveTransform: {
      Token w = tok.next();
      if (w.kind == TokenKind::Word && w.text == "All")
        target_.activeTransformAll(loc);
      else if (w.kind == TokenKind::Word && w.text == "StartTime")
        target_.activeTransformStartTime(loc);
      else if (w.kind == TokenKind::Word && w.text == "EndTime")
        target_.activeTransformEndTime(loc);
      else
        throw SceneError(
            w.loc, "'ActiveTransform' needs All, StartTime or EndTime, found " + describeToken(w));
      break;
    }
    case D::AttributeBegin:
      target_.attributeBegin(loc);
      break;
    case D::AttributeEnd:
      target_.attributeEnd(loc);
      break;
    case D::ConcatTransform: {
      std::vector<Float> m = numbers(tok, t, 16);
      target_.concatTransform(m.data(), loc);
      break;
    }
    case D::Transform: {
      std::vector<Float> m = numbers(tok, t, 16);
      target_.transform(m.data(), loc);
      break;
    }
    case D::CoordinateSystem:
      target_.coordinateSystem(quoted(tok, t, "a name"), loc);
      break;
    case D::CoordSysTransform:
      target_.coordSysTransform(quoted(tok, t, "a name"), loc);
      break;
    case D::Identity:
      target_.identity(loc);
      break;
    case D::Import:  // pbrt-v4's Import: for a parse-only reader, the same as Include
    case D::Include:
      include(tok, t);
      break;
    case D::LookAt: {
      std::vector<Float> v = numbers(tok, t, 9);
      target_.lookAt(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], loc);
      break;
    }
    case D::MediumInterface: {
      std::string inside = quoted(tok, t, "a medium name");
      std::string outside = inside;  // one name: the same medium on both sides (pbrt-v3)
      if (tok.peek().kind == TokenKind::String) outside = tok.next().text;
      target_.mediumInterface(inside, outside, loc);
      break;
    }
    case D::NamedMaterial:
      target_.namedMaterial(quoted(tok, t, "a material name"), loc);
      break;
    case D::ObjectBegin:
      target_.objectBegin(quoted(tok, t, "an object name"), loc);
      break;
    case D::ObjectEnd:
      target_.objectEnd(loc);
      break;
    case D::ObjectInstance:
      target_.objectInstance(quoted(tok, t, "an object name"), loc);
      break;
    case D::Option: {
      ParamSet ps;
      if (tok.peek().kind != TokenKind::String)
        throw SceneError(tok.peek().loc, "'Option' needs a \"type name\" declaration, found " +
                                             describeToken(tok.peek()));
      parameter(tok, ps);
      warn(loc, "Option \"" + ps.items()[0].name + "\" is not supported; ignored");
      break;
    }
    case D::ReverseOrientation:
      target_.reverseOrientation(loc);
      break;
    case D::Rotate: {
      std::vector<Float> v = numbers(tok, t, 4);
      target_.rotate(v[0], v[1], v[2], v[3], loc);
      break;
    }
    case D::Scale: {
      std::vector<Float> v = numbers(tok, t, 3);
      target_.scale(v[0], v[1], v[2], loc);
      break;
    }
    case D::Translate: {
      std::vector<Float> v = numbers(tok, t, 3);
      target_.translate(v[0], v[1], v[2], loc);
      break;
    }
    case D::SearchPath:
      target_.searchPath(quoted(tok, t, "a path"), loc);
      break;
    case D::Texture: {
      std::string name = quoted(tok, t, "a texture name");
      std::string type = quoted(tok, t, "a texture type (\"float\" or \"spectrum\")");
      std::string cls = quoted(tok, t, "a texture class");
      ParamSet ps = params(tok);
      target_.texture(name, type, cls, std::move(ps), loc);
      break;
    }
    case D::TransformBegin:
      target_.transformBegin(loc);
      break;
    case D::TransformEnd:
      target_.transformEnd(loc);
      break;
    case D::TransformTimes: {
      std::vector<Float> v = numbers(tok, t, 2);
      target_.transformTimes(v[0], v[1], loc);
      break;
    }
    case D::WorldBegin:
      target_.worldBegin(loc);
      break;
    case D::WorldEnd:
      target_.worldEnd(loc);
      break;
  }
}

}  // namespace

void parseFile(const std::string& path, ParserTarget& target, const WarningCallback& warn) {
  std::string text;
  if (path == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  } else {
    text = readWholeFile(path);
  }
  Parser(target, warn, {}).parseText(text, path);
}

void parseString(const std::string& text, const std::string& filename, ParserTarget& target,
                 const WarningCallback& warn, const SceneFileReader& readFile) {
  Parser(target, warn, readFile).parseText(text, filename);
}

}  // namespace candela
