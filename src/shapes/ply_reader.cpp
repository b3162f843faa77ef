// PLY parsing: the header is a list of elements, each with a count and typed properties; the body
// holds every element's entries in header order, as text or as packed binary. Every read is
// bounds-checked, and every count is checked against the bytes left before anything is allocated,
// so malformed files end in FileError, never in a crash or a huge allocation.
#include "shapes/ply_reader.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <climits>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <system_error>

#include "core/error.h"

namespace candela {

namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

size_t typeSize(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 1;
}

bool isFloatType(PlyType t) { return t == PlyType::Float32 || t == PlyType::Float64; }

std::optional<PlyType> parseType(std::string_view s) {
  // Both the original names and the sized aliases appear in the wild.
  if (s == "char" || s == "int8") return PlyType::Int8;
  if (s == "uchar" || s == "uint8") return PlyType::UInt8;
  if (s == "short" || s == "int16") return PlyType::Int16;
  if (s == "ushort" || s == "uint16") return PlyType::UInt16;
  if (s == "int" || s == "int32") return PlyType::Int32;
  if (s == "uint" || s == "uint32") return PlyType::UInt32;
  if (s == "float" || s == "float32") return PlyType::Float32;
  if (s == "double" || s == "float64") return PlyType::Float64;
  return std::nullopt;
}

// Vertex attributes candela keeps, as slots into a per-vertex value array.
enum Slot { kX, kY, kZ, kNX, kNY, kNZ, kU, kV, kNumSlots };

struct Property {
  std::string name;
  PlyType type = PlyType::Float32;  // the value type, or the item type of a list
  bool isList = false;
  PlyType countType = PlyType::UInt8;
  int slot = -1;             // vertex element: which Slot this fills, or -1 to skip
  bool faceIndices = false;  // face element: the vertex index list
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
  // Fewest bytes (binary) or tokens (ASCII) one entry can take: the guard on count.
  uint64_t minBinarySize() const {
    uint64_t n = 0;
    for (const Property& p : properties) n += typeSize(p.isList ? p.countType : p.type);
    return n;
  }
};

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  size_t bodyOffset = 0;
};

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

Header parseHeader(std::string_view bytes, const std::string& path) {
  auto bad = [&](const std::string& what) { return FileError(path, "bad PLY header: " + what); };
  Header h;
  bool sawFormat = false;
  size_t pos = 0;
  int lineNumber = 0;
  while (true) {
    size_t eol = bytes.find('\n', pos);
    if (eol == std::string_view::npos)
      throw bad(lineNumber == 0 ? "not a PLY file" : "no end_header line");
    std::string_view line = bytes.substr(pos, eol - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = eol + 1;
    ++lineNumber;
    const std::string where = " (header line " + std::to_string(lineNumber) + ")";
    std::vector<std::string_view> w = splitWords(line);
    if (lineNumber == 1) {
      if (w.size() != 1 || w[0] != "ply") throw bad("not a PLY file (first line is not 'ply')");
      continue;
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (w.size() != 3 || sawFormat) throw bad("malformed format line" + where);
      if (w[1] == "ascii")
        h.format = Format::Ascii;
      else if (w[1] == "binary_little_endian")
        h.format = Format::BinaryLittleEndian;
      else if (w[1] == "binary_big_endian")
        h.format = Format::BinaryBigEndian;
      else
        throw FileError(path, "unsupported PLY format '" + std::string(w[1]) + "'" + where);
      if (w[2] != "1.0" && w[2] != "1")
        throw FileError(path, "unsupported PLY version '" + std::string(w[2]) + "'" + where);
      sawFormat = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) throw bad("malformed element line" + where);
      Element e;
      e.name = std::string(w[1]);
      auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
      if (ec != std::errc() || end != w[2].data() + w[2].size())
        throw bad("bad element count '" + std::string(w[2]) + "'" + where);
      h.elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      if (h.elements.empty()) throw bad("property before any element" + where);
      Property p;
      if (w.size() == 3) {
        auto t = parseType(w[1]);
        if (!t) throw bad("unknown property type '" + std::string(w[1]) + "'" + where);
        p.type = *t;
        p.name = std::string(w[2]);
      } else if (w.size() == 5 && w[1] == "list") {
        auto ct = parseType(w[2]), it = parseType(w[3]);
        if (!ct || !it) throw bad("unknown list type" + where);
        if (isFloatType(*ct)) throw bad("list count type must be an integer type" + where);
        p.isList = true;
        p.countType = *ct;
        p.type = *it;
        p.name = std::string(w[4]);
      } else {
        throw bad("malformed property line" + where);
      }
      h.elements.back().properties.push_back(std::move(p));
    } else if (w[0] == "end_header") {
      if (!sawFormat) throw bad("no format line");
      h.bodyOffset = pos;
      return h;
    } else {
      throw bad("unknown keyword '" + std::string(w[0]) + "'" + where);
    }
  }
}

// Sequential reads from a binary body; every read checks the bytes left.
class BinaryReader {
 public:
  BinaryReader(std::string_view body, bool swapBytes, const std::string& path)
      : p_(body.data()), end_(body.data() + body.size()), swap_(swapBytes), path_(path) {}
  uint64_t remaining() const { return uint64_t(end_ - p_); }
  void skip(uint64_t n, const char* what) {
    if (n > remaining()) truncated(what);
    p_ += n;
  }
  double readFloat(PlyType t, const char* what) {
    switch (t) {
      case PlyType::Int8:
        return load<int8_t>(what);
      case PlyType::UInt8:
        return load<uint8_t>(what);
      case PlyType::Int16:
        return load<int16_t>(what);
      case PlyType::UInt16:
        return load<uint16_t>(what);
      case PlyType::Int32:
        return load<int32_t>(what);
      case PlyType::UInt32:
        return load<uint32_t>(what);
      case PlyType::Float32:
        return load<float>(what);
      case PlyType::Float64:
        return load<double>(what);
    }
    return 0;
  }
  // Integers (counts, indices) stay exact; callers only pass integer types.
  int64_t readInt(PlyType t, const char* what) {
    switch (t) {
      case PlyType::Int8:
        return load<int8_t>(what);
      case PlyType::UInt8:
        return load<uint8_t>(what);
      case PlyType::Int16:
        return load<int16_t>(what);
      case PlyType::UInt16:
        return load<uint16_t>(what);
      case PlyType::Int32:
        return load<int32_t>(what);
      case PlyType::UInt32:
        return load<uint32_t>(what);
      default:
        return int64_t(readFloat(t, what));
    }
  }
  // Skips one scalar value.
  void skipValue(PlyType t, const char* what) { skip(typeSize(t), what); }
  // Whether n more items of type t can possibly follow.
  bool fits(uint64_t n, PlyType t) const { return n <= remaining() / typeSize(t); }

 private:
  template <typename T>
  T load(const char* what) {
    if (sizeof(T) > remaining()) truncated(what);
    unsigned char b[sizeof(T)];
    std::memcpy(b, p_, sizeof(T));
    if (swap_) std::reverse(b, b + sizeof(T));
    T v;
    std::memcpy(&v, b, sizeof(T));
    p_ += sizeof(T);
    return v;
  }
  [[noreturn]] void truncated(const char* what) const {
    throw FileError(path_, std::string("truncated PLY file: data ends inside ") + what);
  }
  const char* p_;
  const char* end_;
  bool swap_;
  const std::string& path_;
};

// Whitespace-separated tokens of an ASCII body.
class AsciiReader {
 public:
  AsciiReader(std::string_view body, const std::string& path)
      : p_(body.data()), end_(body.data() + body.size()), path_(path) {}
  uint64_t remaining() const { return uint64_t(end_ - p_); }
  double readFloat(PlyType, const char* what) {
    std::string_view tok = next(what);
    if (!tok.empty() && tok[0] == '+') tok.remove_prefix(1);  // from_chars rejects '+'
    double v = 0;
    auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec != std::errc() || end != tok.data() + tok.size()) badValue(tok, what);
    return v;
  }
  int64_t readInt(PlyType t, const char* what) {
    if (isFloatType(t)) return int64_t(readFloat(t, what));
    std::string_view tok = next(what);
    if (!tok.empty() && tok[0] == '+') tok.remove_prefix(1);
    int64_t v = 0;
    auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec != std::errc() || end != tok.data() + tok.size()) badValue(tok, what);
    return v;
  }
  void skipValue(PlyType, const char* what) { next(what); }
  void skip(uint64_t nTokens, const char* what) {
    for (uint64_t i = 0; i < nTokens; ++i) next(what);
  }
  // n tokens need at least 2n - 1 bytes.
  bool fits(uint64_t n, PlyType) const { return n <= remaining() / 2 + 1; }

 private:
  static bool space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
  }
  std::string_view next(const char* what) {
    while (p_ < end_ && space(*p_)) ++p_;
    if (p_ == end_)
      throw FileError(path_, std::string("truncated PLY file: data ends inside ") + what);
    const char* start = p_;
    while (p_ < end_ && !space(*p_)) ++p_;
    return std::string_view(start, size_t(p_ - start));
  }
  [[noreturn]] void badValue(std::string_view tok, const char* what) const {
    throw FileError(path_, "bad PLY value '" + std::string(tok.substr(0, 32)) + "' in " + what);
  }
  const char* p_;
  const char* end_;
  const std::string& path_;
};

// Decides what each property of the vertex and face elements means; throws for meshes candela
// cannot use (no positions, face indices that are not an integer list).
void assignRoles(Header& h, const std::string& path, bool* hasNormals, bool* hasUVs) {
  *hasNormals = *hasUVs = false;
  for (Element& e : h.elements) {
    auto find = [&](const char* name) -> Property* {
      for (Property& p : e.properties)
        if (p.name == name && !p.isList) return &p;
      return nullptr;
    };
    if (e.name == "vertex") {
      Property *x = find("x"), *y = find("y"), *z = find("z");
      if (!x || !y || !z)
        throw FileError(path, "unsupported PLY mesh: vertex element lacks x, y or z");
      x->slot = kX, y->slot = kY, z->slot = kZ;
      Property *nx = find("nx"), *ny = find("ny"), *nz = find("nz");
      if (nx && ny && nz) {
        nx->slot = kNX, ny->slot = kNY, nz->slot = kNZ;
        *hasNormals = true;
      }
      // The first complete pair of the usual texture coordinate names wins.
      const char* uvNames[][2] = {
          {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
      for (auto& names : uvNames) {
        Property *u = find(names[0]), *v = find(names[1]);
        if (u && v) {
          u->slot = kU, v->slot = kV;
          *hasUVs = true;
          break;
        }
      }
    } else if (e.name == "face") {
      bool found = false;
      for (Property& p : e.properties) {
        if (found || (p.name != "vertex_indices" && p.name != "vertex_index")) continue;
        if (!p.isList || isFloatType(p.type))
          throw FileError(path,
                          "unsupported PLY mesh: face " + p.name + " must be a list of integers");
        p.faceIndices = found = true;
      }
      if (!found && e.count > 0)
        throw FileError(path, "unsupported PLY mesh: face element has no vertex_indices list");
    }
  }
}

template <typename Reader>
void readBody(const Header& h, Reader& in, bool binary, bool hasNormals, bool hasUVs,
              const std::string& path, PlyMesh& mesh) {
  uint64_t vertexCount = 0;
  for (const Element& e : h.elements)
    if (e.name == "vertex") vertexCount = e.count;
  if (vertexCount > uint64_t(INT_MAX))
    throw FileError(
        path, "unsupported PLY mesh: too many vertices (" + std::to_string(vertexCount) + ")");

  std::vector<int64_t> face;  // reused per face
  uint64_t faceNumber = 0;
  for (const Element& e : h.elements) {
    if (e.properties.empty() || e.count == 0) continue;  // nothing stored for it
    // A count the remaining bytes cannot hold is a truncated (or lying) file: reject it before
    // allocating or looping.
    uint64_t perEntry = binary ? e.minBinarySize() : 2 * e.properties.size() - 1;
    if (e.count > in.remaining() / perEntry + (binary ? 0 : 1))
      throw FileError(path, "truncated PLY file: element '" + e.name + "' declares " +
                                std::to_string(e.count) + " entries but only " +
                                std::to_string(in.remaining()) + " bytes remain");
    const bool isVertex = e.name == "vertex", isFace = e.name == "face";
    const char* what = isVertex ? "vertex data" : (isFace ? "face data" : "element data");
    if (isVertex) {
      mesh.positions.reserve(size_t(e.count));
      if (hasNormals) mesh.normals.reserve(size_t(e.count));
      if (hasUVs) mesh.uvs.reserve(size_t(e.count));
    }
    for (uint64_t i = 0; i < e.count; ++i) {
      double v[kNumSlots] = {};
      for (const Property& p : e.properties) {
        if (!p.isList) {
          if (p.slot >= 0)
            v[p.slot] = in.readFloat(p.type, what);
          else
            in.skipValue(p.type, what);
          continue;
        }
        int64_t n = in.readInt(p.countType, what);
        if (n < 0 || !in.fits(uint64_t(n), p.type))
          throw FileError(path, "truncated or corrupt PLY file: list '" + p.name + "' of " +
                                    std::to_string(n) + " items in element '" + e.name + "'");
        if (!p.faceIndices) {
          in.skip(binary ? uint64_t(n) * typeSize(p.type) : uint64_t(n), what);
          continue;
        }
        face.clear();
        for (int64_t k = 0; k < n; ++k) {
          int64_t index = in.readInt(p.type, what);
          if (index < 0 || uint64_t(index) >= vertexCount)
            throw FileError(path, "PLY face " + std::to_string(faceNumber) + ": vertex index " +
                                      std::to_string(index) + " out of range (" +
                                      std::to_string(vertexCount) + " vertices)");
          face.push_back(index);
        }
        // Triangles as they are, quads as (0 1 2)(0 2 3), larger polygons as a fan; points
        // and lines bound no area and are dropped.
        for (size_t k = 1; k + 1 < face.size(); ++k) {
          mesh.indices.push_back(int(face[0]));
          mesh.indices.push_back(int(face[k]));
          mesh.indices.push_back(int(face[k + 1]));
        }
      }
      if (isVertex) {
        mesh.positions.emplace_back(Float(v[kX]), Float(v[kY]), Float(v[kZ]));
        if (hasNormals) mesh.normals.emplace_back(Float(v[kNX]), Float(v[kNY]), Float(v[kNZ]));
        if (hasUVs) mesh.uvs.emplace_back(Float(v[kU]), Float(v[kV]));
      } else if (isFace) {
        ++faceNumber;
      }
    }
  }
}

}  // namespace

PlyMesh parsePly(std::string_view bytes, const std::string& path) {
  Header h = parseHeader(bytes, path);
  bool hasNormals = false, hasUVs = false;
  assignRoles(h, path, &hasNormals, &hasUVs);
  int vertexElements = 0, faceElements = 0;
  for (const Element& e : h.elements) {
    vertexElements += e.name == "vertex";
    faceElements += e.name == "face";
  }
  if (vertexElements == 0) throw FileError(path, "unsupported PLY mesh: no vertex element");
  if (vertexElements > 1 || faceElements > 1)
    throw FileError(path, "bad PLY header: more than one vertex or face element");

  PlyMesh mesh;
  std::string_view body = bytes.substr(h.bodyOffset);
  if (h.format == Format::Ascii) {
    AsciiReader in(body, path);
    readBody(h, in, false, hasNormals, hasUVs, path, mesh);
  } else {
    // Swap when the file's byte order differs from this machine's.
    bool fileLittle = h.format == Format::BinaryLittleEndian;
    bool hostLittle = std::endian::native == std::endian::little;
    BinaryReader in(body, fileLittle != hostLittle, path);
    readBody(h, in, true, hasNormals, hasUVs, path, mesh);
  }
  return mesh;
}

PlyMesh readPly(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw FileError(path, "cannot read PLY mesh: no such file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw FileError(path, "cannot read PLY mesh: cannot open file");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw FileError(path, "cannot read PLY mesh: " + ec.message());
  std::string contents(size_t(size), '\0');
  if (!file.read(contents.data(), std::streamsize(size)))
    throw FileError(path, "cannot read PLY mesh: read error");
  return parsePly(contents, path);
}

}  // namespace candela
