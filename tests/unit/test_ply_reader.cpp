// PLY reader: the same mesh written as ASCII, binary little- and big-endian, with quads, a
// pentagon, normals, texture coordinates and properties/elements the reader must skip; and
// malformed files, which must end in FileError, never in a crash.
#include "shapes/ply_reader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.h"
#include "support/temp_dir.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

enum class Fmt { Ascii, LittleEndian, BigEndian };

// Builds a PLY body value by value in the chosen encoding.
class Body {
 public:
  explicit Body(Fmt f) : f_(f) {}
  template <typename T>
  Body& put(T v) {
    if (f_ == Fmt::Ascii) {
      std::ostringstream os;
      os << std::setprecision(17);
      if constexpr (sizeof(T) == 1 && std::is_integral_v<T>)
        os << int(v);
      else
        os << v;
      bytes_ += os.str() + " ";
    } else {
      char b[sizeof(T)];
      std::memcpy(b, &v, sizeof(T));
      bool fileLittle = f_ == Fmt::LittleEndian;
      if (fileLittle != (std::endian::native == std::endian::little))
        std::reverse(b, b + sizeof(T));
      bytes_.append(b, sizeof(T));
    }
    return *this;
  }
  Body& newline() {
    if (f_ == Fmt::Ascii) bytes_ += "\n";
    return *this;
  }
  const std::string& str() const { return bytes_; }

 private:
  Fmt f_;
  std::string bytes_;
};

const char* formatLine(Fmt f) {
  switch (f) {
    case Fmt::Ascii:
      return "format ascii 1.0\n";
    case Fmt::LittleEndian:
      return "format binary_little_endian 1.0\n";
    case Fmt::BigEndian:
      return "format binary_big_endian 1.0\n";
  }
  return "";
}

// The reference mesh: 7 vertices; a quad, a triangle, a pentagon and a two-vertex "face" that
// the reader drops.
constexpr int kVertices = 7;
Point3f position(int i) { return {Float(i), 2.f * i + 0.5f, -0.25f * i}; }
Normal3f normal(int i) { return {0.125f * i, 1.f, -0.5f}; }
Point2f uv(int i) { return {0.125f * i, 1.f - 0.0625f * i}; }
const std::vector<std::vector<int>> kFaces = {{0, 1, 2, 3}, {0, 3, 4}, {0, 1, 5, 6, 2}, {1, 2}};
const std::vector<int> kTriangles = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 1, 5, 0, 5, 6, 0, 6, 2};

// Float vertices with normals, colours (skipped) and u v; a face element with an extra scalar.
std::string meshWithFloats(Fmt f) {
  std::string header = std::string("ply\n") + formatLine(f) +
                       "comment written by the candela tests\n"
                       "obj_info nothing to see\n"
                       "element vertex 7\n"
                       "property float x\nproperty float y\nproperty float z\n"
                       "property float nx\nproperty float ny\nproperty float nz\n"
                       "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                       "property float u\nproperty float v\n"
                       "element face 4\n"
                       "property list uchar int vertex_indices\n"
                       "property int flags\n"
                       "end_header\n";
  Body b(f);
  for (int i = 0; i < kVertices; ++i) {
    Point3f p = position(i);
    Normal3f n = normal(i);
    Point2f t = uv(i);
    b.put(float(p.x)).put(float(p.y)).put(float(p.z));
    b.put(float(n.x)).put(float(n.y)).put(float(n.z));
    b.put(uint8_t(200)).put(uint8_t(100)).put(uint8_t(i));
    b.put(float(t.x)).put(float(t.y)).newline();
  }
  for (const auto& face : kFaces) {
    b.put(uint8_t(face.size()));
    for (int v : face) b.put(int32_t(v));
    b.put(int32_t(-7)).newline();
  }
  return header + b.str();
}

// Double positions, s t coordinates, list properties and whole elements to skip, an int count
// with unsigned indices, and the face element between two other elements.
std::string meshWithDoubles(Fmt f) {
  std::string header = std::string("ply\n") + formatLine(f) +
                       "element vertex 7\n"
                       "property double x\nproperty double y\nproperty double z\n"
                       "property short quality\n"
                       "property double s\nproperty double t\n"
                       "property list uchar float weights\n"
                       "property float nx\nproperty float ny\nproperty float nz\n"
                       "element edge 2\n"
                       "property int vertex1\nproperty int vertex2\nproperty uchar crease\n"
                       "element face 4\n"
                       "property list int uint vertex_index\n"
                       "property list uchar float texcoord\n"
                       "element material 1\n"
                       "property double shininess\n"
                       "end_header\n";
  Body b(f);
  for (int i = 0; i < kVertices; ++i) {
    Point3f p = position(i);
    Normal3f n = normal(i);
    Point2f t = uv(i);
    b.put(double(p.x)).put(double(p.y)).put(double(p.z)).put(int16_t(-300 + i));
    b.put(double(t.x)).put(double(t.y));
    b.put(uint8_t(i % 3));
    for (int k = 0; k < i % 3; ++k) b.put(float(k) * 0.5f);
    b.put(float(n.x)).put(float(n.y)).put(float(n.z)).newline();
  }
  b.put(int32_t(0)).put(int32_t(1)).put(uint8_t(255)).newline();
  b.put(int32_t(2)).put(int32_t(3)).put(uint8_t(0)).newline();
  for (const auto& face : kFaces) {
    b.put(int32_t(face.size()));
    for (int v : face) b.put(uint32_t(v));
    b.put(uint8_t(2 * face.size()));
    for (size_t k = 0; k < 2 * face.size(); ++k) b.put(0.25f * float(k));
    b.newline();
  }
  b.put(42.0).newline();
  return header + b.str();
}

void expectReferenceMesh(const PlyMesh& m) {
  ASSERT_EQ(m.positions.size(), size_t(kVertices));
  ASSERT_EQ(m.normals.size(), size_t(kVertices));
  ASSERT_EQ(m.uvs.size(), size_t(kVertices));
  for (int i = 0; i < kVertices; ++i) {
    EXPECT_EQ(m.positions[i], position(i)) << "vertex " << i;
    EXPECT_EQ(m.normals[i], normal(i)) << "vertex " << i;
    EXPECT_EQ(m.uvs[i], uv(i)) << "vertex " << i;
  }
  EXPECT_EQ(m.indices, kTriangles);
}

// Expects readPly(path) to throw FileError whose message names the path and contains `what`.
void expectFileError(const std::string& path, const std::string& what) {
  try {
    readPly(path);
    ADD_FAILURE() << "no FileError for " << path;
  } catch (const FileError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

TEST(PlyReader, AsciiFloats) {
  TempDir dir("ply");
  expectReferenceMesh(readPly(dir.write("a.ply", meshWithFloats(Fmt::Ascii))));
}

TEST(PlyReader, BinaryLittleEndianFloats) {
  TempDir dir("ply");
  expectReferenceMesh(readPly(dir.write("le.ply", meshWithFloats(Fmt::LittleEndian))));
}

TEST(PlyReader, BinaryBigEndianFloats) {
  TempDir dir("ply");
  expectReferenceMesh(readPly(dir.write("be.ply", meshWithFloats(Fmt::BigEndian))));
}

TEST(PlyReader, DoublesListsAndExtraElementsInEveryFormat) {
  TempDir dir("ply");
  for (Fmt f : {Fmt::Ascii, Fmt::LittleEndian, Fmt::BigEndian}) {
    SCOPED_TRACE(int(f));
    expectReferenceMesh(readPly(dir.write("d.ply", meshWithDoubles(f))));
  }
}

TEST(PlyReader, AsciiWithCrLfFaceFirstAndTextureUV) {
  // Windows line endings, the face element before the vertices, texture_u/texture_v names.
  std::string text =
      "ply\r\nformat ascii 1.0\r\nelement face 2\r\nproperty list uchar int vertex_indices\r\n"
      "element vertex 4\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "property float texture_u\r\nproperty float texture_v\r\nend_header\r\n"
      "3 0 1 2\r\n4 0 1 2 3\r\n"
      "0 0 0 0 0\r\n1 0 0 1 0\r\n1 1 0 1 1\r\n+0 1 -0 0 1e0\r\n";
  PlyMesh m = parsePly(text, "crlf.ply");
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_TRUE(m.normals.empty());
  ASSERT_EQ(m.uvs.size(), 4u);
  EXPECT_EQ(m.positions[3], Point3f(0, 1, 0));
  EXPECT_EQ(m.uvs[3], Point2f(0, 1));
  EXPECT_EQ(m.indices, (std::vector<int>{0, 1, 2, 0, 1, 2, 0, 2, 3}));
}

TEST(PlyReader, IntegerVertexProperties) {
  std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty int8 x\n"
      "property int16 y\nproperty uint32 z\nproperty ushort u\nproperty uint8 v\n"
      "element face 1\nproperty list uint8 uint16 vertex_indices\nend_header\n";
  Body b(Fmt::LittleEndian);
  b.put(int8_t(-3)).put(int16_t(-1000)).put(uint32_t(70000)).put(uint16_t(65535)).put(uint8_t(1));
  b.put(int8_t(1)).put(int16_t(2)).put(uint32_t(3)).put(uint16_t(4)).put(uint8_t(5));
  b.put(int8_t(0)).put(int16_t(0)).put(uint32_t(0)).put(uint16_t(0)).put(uint8_t(0));
  b.put(uint8_t(3)).put(uint16_t(2)).put(uint16_t(1)).put(uint16_t(0));
  PlyMesh m = parsePly(header + b.str(), "ints.ply");
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[0], Point3f(-3, -1000, 70000));
  EXPECT_EQ(m.uvs[0], Point2f(65535, 1));
  EXPECT_EQ(m.indices, (std::vector<int>{2, 1, 0}));
}

TEST(PlyReader, MissingFileThrows) {
  TempDir dir("ply");
  expectFileError("/nonexistent/candela/mesh.ply", "no such file");
}

TEST(PlyReader, TruncatedBinaryThrows) {
  TempDir dir("ply");
  for (Fmt f : {Fmt::LittleEndian, Fmt::BigEndian}) {
    std::string full = meshWithFloats(f);
    // Cut inside the face data, inside the vertex data and right after the header.
    for (size_t cut : {size_t(3), size_t(60), size_t(200)}) {
      std::string path = dir.write("t.ply", full.substr(0, full.size() - cut));
      expectFileError(path, "truncated");
    }
  }
}

TEST(PlyReader, TruncatedAsciiThrows) {
  TempDir dir("ply");
  std::string full = meshWithFloats(Fmt::Ascii);
  std::string path = dir.write("t.ply", full.substr(0, full.size() - 12));
  expectFileError(path, "truncated");
}

TEST(PlyReader, IndexOutOfRangeThrows) {
  TempDir dir("ply");
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n";
  expectFileError(dir.write("range.ply", text), "out of range");
  std::string negative = text.substr(0, text.size() - 8) + "3 0 -1 2\n";
  expectFileError(dir.write("negative.ply", negative), "out of range");
}

TEST(PlyReader, GarbageHeaderThrows) {
  TempDir dir("ply");
  expectFileError(dir.write("empty.ply", ""), "header");
  expectFileError(dir.write("text.ply", "hello world\nthis is not a mesh\n"), "header");
  std::string bytes(4096, '\0');
  std::mt19937 rng(7);
  for (char& c : bytes) c = char(rng());
  expectFileError(dir.write("random.ply", bytes), "header");
  expectFileError(dir.write("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"), "header");
  expectFileError(dir.write("type.ply",
                            "ply\nformat ascii 1.0\nelement vertex 1\nproperty flaot x\n"
                            "end_header\n0\n"),
                  "header");
  expectFileError(dir.write("count.ply",
                            "ply\nformat ascii 1.0\nelement vertex -4\nproperty float x\n"
                            "end_header\n"),
                  "header");
  expectFileError(dir.write("keyword.ply", "ply\nformat ascii 1.0\nbanana\nend_header\n"),
                  "header");
}

TEST(PlyReader, UnsupportedContentThrows) {
  TempDir dir("ply");
  expectFileError(dir.write("fmt.ply",
                            "ply\nformat binary_middle_endian 1.0\nelement vertex 0\n"
                            "end_header\n"),
                  "unsupported");
  expectFileError(dir.write("noxyz.ply",
                            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                            "property float y\nend_header\n0 0\n"),
                  "unsupported");
  expectFileError(dir.write("noverts.ply",
                            "ply\nformat ascii 1.0\nelement face 0\n"
                            "property list uchar int vertex_indices\nend_header\n"),
                  "unsupported");
  expectFileError(dir.write("floatidx.ply",
                            "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 0\n"
                            "property list uchar float vertex_indices\nend_header\n"),
                  "unsupported");
}

TEST(PlyReader, HugeCountsAreRejectedBeforeAllocating) {
  // Counts far beyond what the file holds must not reach an allocation or a long loop.
  std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000000\n"
      "property float x\nproperty float y\nproperty float z\nend_header\n";
  EXPECT_THROW(parsePly(header + std::string(24, '\0'), "huge.ply"), FileError);
  std::string list =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty uchar x\n"
      "property uchar y\nproperty uchar z\nelement face 1\n"
      "property list int int vertex_indices\nend_header\n";
  Body b(Fmt::LittleEndian);
  for (int i = 0; i < 9; ++i) b.put(uint8_t(i));
  b.put(int32_t(2000000000)).put(int32_t(0));
  EXPECT_THROW(parsePly(list + b.str(), "hugelist.ply"), FileError);
  // An element with no properties holds no data whatever its count.
  std::string empty =
      "ply\nformat ascii 1.0\nelement nothing 18446744073709551615\nelement vertex 1\n"
      "property float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n";
  EXPECT_EQ(parsePly(empty, "empty.ply").positions.size(), 1u);
}

TEST(PlyReader, MutatedFilesNeverCrash) {
  // Random byte flips and cuts of valid files: each parse either succeeds or throws FileError.
  std::mt19937 rng(12345);
  std::vector<std::string> seeds = {meshWithFloats(Fmt::Ascii), meshWithFloats(Fmt::LittleEndian),
                                    meshWithDoubles(Fmt::BigEndian), meshWithDoubles(Fmt::Ascii)};
  int parsed = 0, rejected = 0;
  for (int iter = 0; iter < 4000; ++iter) {
    std::string bytes = seeds[size_t(iter) % seeds.size()];
    int flips = 1 + int(rng() % 4);
    for (int k = 0; k < flips; ++k) bytes[rng() % bytes.size()] = char(rng());
    if (rng() % 4 == 0) bytes.resize(rng() % bytes.size());
    try {
      PlyMesh m = parsePly(bytes, "mutated.ply");
      for (int i : m.indices) ASSERT_TRUE(i >= 0 && size_t(i) < m.positions.size());
      ++parsed;
    } catch (const FileError&) {
      ++rejected;
    }
  }
  // Both outcomes occur, so the loop exercises the error paths and the successful ones.
  EXPECT_GT(parsed, 100) << rejected;
  EXPECT_GT(rejected, 100) << parsed;
}

}  // namespace
}  // namespace candela
