// Bad input, made inside the test: each file is refused (or loaded with a
// warning) for its own cause, named in the message, and nothing crashes,
// hangs or comes out NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "models/test/gltf_test_files.h"

namespace {

using namespace ig::models;
using namespace ig::models::test;

class BadInput : public ModelFilesTest {};

std::vector<std::uint8_t> read_all(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

const std::string kAircraft = std::string(IG_BIN_DIR) + "/models/aircraft.glb";

// ------------------------------------------------------ files and bytes ---

TEST_F(BadInput, MissingEmptyAndFolder) {
  expect_refused(path("nope.glb"), {"no such file"});
  expect_refused(write("empty.glb", ""), {"empty file (0 bytes)"});
  std::filesystem::create_directories(path("folder.gltf"));
  expect_refused(path("folder.gltf"), {"is a folder"});
}

TEST_F(BadInput, TruncatedGlb) {
  const std::vector<std::uint8_t> whole = read_all(kAircraft);
  ASSERT_GT(whole.size(), 1000u) << kAircraft;
  // Cut anywhere: inside the header, the JSON chunk, the BIN chunk.
  const std::vector<std::uint8_t> head(whole.begin(), whole.begin() + 10);
  expect_refused(write("head.glb", head), {"truncated glTF binary", "shorter than the 12-byte header"});
  for (const std::size_t keep : {std::size_t(30), whole.size() / 2, whole.size() - 1}) {
    const std::vector<std::uint8_t> part(whole.begin(), whole.begin() + std::ptrdiff_t(keep));
    expect_refused(write("cut.glb", part), {"truncated glTF binary", "header says " + std::to_string(whole.size())});
  }
}

// The BIN chunk claims to run exactly to the file's end, forgetting its own
// 8-byte header: TinyGLTF 2.7.0 alone would read 8 bytes past the buffer.
TEST_F(BadInput, BinChunkLongerThanTheFile) {
  GltfBuilder b;
  b.one_triangle();
  std::vector<std::uint8_t> glb = b.glb();
  const std::size_t json_len = std::size_t(glb[12]) | std::size_t(glb[13]) << 8;
  const std::size_t bin_at = 20 + json_len;
  const std::uint32_t lie = std::uint32_t(glb.size() - bin_at);  // payload + header
  for (int i = 0; i < 4; ++i) glb[bin_at + std::size_t(i)] = std::uint8_t(lie >> (8 * i));
  expect_refused(write("lie.glb", glb), {"BIN chunk", "claims " + std::to_string(lie) + " bytes"});
}

TEST_F(BadInput, GarbledBytes) {
  std::string noise(4096, '\0');
  std::uint32_t x = 12345;
  for (char& c : noise) {
    x = x * 1664525u + 1013904223u;
    c = char(x >> 24);
  }
  expect_refused(write("noise.glb", noise), {"neither a glTF binary", "nor valid glTF JSON"});
  expect_refused(write("text.gltf", "this is not JSON\n"), {"nor valid glTF JSON", "parse error"});
  expect_refused(write("array.gltf", "[1, 2, 3]"), {"the glTF JSON is not an object (it is array)"});
  expect_refused(write("noasset.gltf", "{\"nodes\": []}"), {"no \"asset\" object"});
  expect_refused(write("v1.gltf", R"({"asset": {"version": "1.0"}})"), {"glTF version \"1.0\" is not supported"});
  // The aircraft with its JSON chunk overwritten by noise.
  std::vector<std::uint8_t> glb = read_all(kAircraft);
  for (std::size_t i = 20; i < 60; ++i) glb[i] = std::uint8_t(noise[i]);
  expect_refused(write("garbled.glb", glb), {"JSON chunk is not valid JSON"});
  // A GLB of another version, and one whose first chunk is not JSON.
  glb = read_all(kAircraft);
  glb[4] = 1;
  expect_refused(write("v1.glb", glb), {"glTF binary version 1 is not supported"});
  glb = read_all(kAircraft);
  glb[16] = 'X';
  expect_refused(write("nojson.glb", glb), {"first chunk is", "not JSON"});
}

// Arrays nested deeper than any glTF needs, in "extras" where TinyGLTF
// converts them recursively: refused before it sees them.
TEST_F(BadInput, DeepJson) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  expect_refused(write("deep.gltf", R"({"asset": {"version": "2.0"}, "extras": )" + deep + "}"),
                 {"JSON nested more than 64 levels deep"});
}

// ------------------------------------------------------------- buffers ---

TEST_F(BadInput, MissingBin) {
  GltfBuilder b;
  b.one_triangle();
  const std::string file = write("nobin.gltf", b.gltf_text("nobin.bin"));  // the .bin never written
  expect_refused(file, {"nobin.bin"});
  // A .bin shorter than the buffer's byteLength says.
  write("short.bin", std::vector<std::uint8_t>(b.bin.begin(), b.bin.end() - 4));
  expect_refused(write("short.gltf", b.gltf_text("short.bin")), {"short.bin"});
}

TEST_F(BadInput, AccessorPastItsBufferView) {
  GltfBuilder b;
  b.one_triangle();
  b.doc["accessors"][0]["count"] = 4;  // 3 positions stored, 4 claimed
  expect_refused(write_gltf("count", b), {"accessor 0", "4 elements", "past the end of bufferView 0"});
  GltfBuilder c;
  c.one_triangle();
  c.doc["accessors"][0]["byteOffset"] = 8;
  expect_refused(write_gltf("offset", c), {"accessor 0", "past the end of bufferView 0"});
  // Counts far beyond anything real, with no data behind them: refused
  // from the count before anything is allocated or read.
  GltfBuilder d;
  d.one_triangle();
  d.doc["accessors"][0]["count"] = 4000000000ull;
  expect_refused(write_gltf("huge", d), {"POSITION (accessor 0): 4000000000 elements, above the cap of 4000000"});
  d.doc["accessors"][1]["count"] = 3000000000ull;  // the indices: a billion triangles
  expect_refused(write_gltf("huge", d), {"1000000000 triangles counting instancing, above the cap of 1000000",
                                         "drawn by 1 node)"});
}

// A GLB buffer of byteLength 0 makes TinyGLTF 2.7.0 throw (it copies to
// data.at(0)): caught, and the file refused.
TEST_F(BadInput, EmptyGlbBuffer) {
  GltfBuilder b;
  b.one_triangle();
  json doc = b.doc;
  doc["buffers"] = json::array({{{"byteLength", 0}}});
  const std::vector<std::uint8_t> glb = GltfBuilder::glb_bytes(doc.dump(), b.bin);
  expect_refused(write("empty_buffer.glb", glb), {"TinyGLTF"});
}

TEST_F(BadInput, BufferViewPastItsBuffer) {
  GltfBuilder b;
  b.one_triangle();
  b.doc["bufferViews"][1]["byteLength"] = 400;  // the index view
  expect_refused(write_gltf("view", b), {"bufferView 1", "runs past the end of buffer 0"});
}

TEST_F(BadInput, StrideSmallerThanAnElement) {
  GltfBuilder b;
  b.one_triangle();
  b.doc["bufferViews"][0]["byteStride"] = 8;  // VEC3 floats are 12 bytes
  expect_refused(write_gltf("stride", b), {"byteStride 8 is smaller than one element (12 bytes)"});
}

// ---------------------------------------------------------- vertex data ---

TEST_F(BadInput, NanAndInfinitePositions) {
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    GltfBuilder b;
    const int pos = b.add_floats({0, 0, 0, 1, 0, 0, 0, bad, 0}, "VEC3");
    b.set_scene({b.add_node("n", b.add_mesh(pos, b.add_indices({0, 1, 2}), kTriangles, -1, "wing"))});
    expect_refused(write_gltf("nan", b), {"mesh 0 ('wing') primitive 0", "vertex 2's POSITION is NaN or infinite"});
  }
}

TEST_F(BadInput, IndexOutOfRange) {
  GltfBuilder b;
  const int pos = b.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  b.set_scene({b.add_node("n", b.add_mesh(pos, b.add_indices({0, 1, 2, 2, 1, 7})))});
  expect_refused(write_gltf("index", b), {"index 7 (index number 5) is out of range (3 vertices)"});
  // Index type must be unsigned.
  GltfBuilder c;
  c.one_triangle();
  c.doc["accessors"][1]["componentType"] = kFloat;
  expect_refused(write_gltf("float_index", c), {"index component type 5126 is not an unsigned integer type"});
}

TEST_F(BadInput, NanNormalsAndTexcoordsAreReplaced) {
  GltfBuilder b;
  const int pos = b.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int nrm = b.add_floats({0, 0, 1, NAN, 0, 1, 0, 0, 1}, "VEC3");
  b.set_scene({b.add_node("n", b.add_mesh(pos, b.add_indices({0, 1, 2})))});
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = nrm;
  const ModelLoad r = expect_loaded(write_gltf("nan_normal", b));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(any_warning(r, {"NORMAL 1 is zero, NaN or infinite", "normals computed"}));
  for (const glm::vec3& n : r.model->meshes[0].primitives[0].normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

// ------------------------------------------------------------- textures ---

// The one triangle with texture coordinates and a material whose base
// colour texture is image 0, `image` (a uri or a bufferView).
GltfBuilder textured_triangle(const json& image) {
  GltfBuilder b;
  b.one_triangle();
  const int uv = b.add_floats({0, 0, 1, 0, 0, 1}, "VEC2");
  b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv;
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  b.doc["materials"] = json::array(
      {{{"name", "painted"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.6, 0.7, 1.0}}, {"baseColorTexture", {{"index", 0}}}}}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  b.doc["images"] = json::array({image});
  return b;
}

// The model loads without the texture, the material keeps its colour, and
// one warning names the image and why.
void expect_untextured(const ModelLoad& r, std::initializer_list<std::string> why) {
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.model->images.empty());
  ASSERT_EQ(r.model->materials.size(), 1u);
  EXPECT_EQ(r.model->materials[0].base_color_image, -1);
  EXPECT_EQ(r.model->materials[0].base_color, glm::vec4(0.5f, 0.6f, 0.7f, 1.0f));
  bool found = false;
  for (const std::string& w : r.warnings) {
    bool all = w.find("drawn untextured") != std::string::npos;
    for (const std::string& p : why) all = all && w.find(p) != std::string::npos;
    found = found || all;
  }
  EXPECT_TRUE(found) << (r.warnings.empty() ? std::string("no warnings") : r.warnings.front());
}

TEST_F(BadInput, MissingTexture) {
  const GltfBuilder b = textured_triangle({{"uri", "livery.png"}});
  expect_untextured(expect_loaded(write_gltf("tex", b)), {"image 0 ('livery.png') not loaded", "file missing"});
  // An empty file is as good as a missing one.
  write("livery.png", "");
  expect_untextured(expect_loaded(write_gltf("tex", b)), {"image 0 ('livery.png') not loaded"});
}

TEST_F(BadInput, BadTextures) {
  const GltfBuilder b = textured_triangle({{"uri", "tex.png"}});
  write("tex.png", "GIF89a, not what glTF allows");
  expect_untextured(expect_loaded(write_gltf("gif", b)), {"image 0 ('tex.png')", "neither PNG nor JPEG"});
  // A PNG header promising 100000 x 100000 pixels: refused from the header,
  // never decoded.
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                   0,    1,   0x86, 0xA0, 0,  1,    0x86, 0xA0, 8, 6, 0, 0, 0};
  write("tex.png", png);
  expect_untextured(expect_loaded(write_gltf("huge", b)), {"100000 x 100000 pixels would pass the cap"});
  // A small PNG header followed by garbage: the decoder's reason.
  png[16] = png[17] = png[20] = png[21] = 0;
  png.resize(200, 0x5A);
  write("tex.png", png);
  expect_untextured(expect_loaded(write_gltf("garbage", b)), {"image 0 ('tex.png') not loaded ("});
}

// An image in a buffer view that runs past its buffer (TinyGLTF hands the
// pointer over unchecked): the image is dropped before a byte is read.
TEST_F(BadInput, TextureViewPastItsBuffer) {
  GltfBuilder b = textured_triangle({{"bufferView", 0}, {"mimeType", "image/png"}});
  const std::uint8_t png_sig[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  const int view = b.add_view(png_sig, sizeof png_sig);
  b.doc["bufferViews"][std::size_t(view)]["byteLength"] = 1 << 20;
  b.doc["images"][0]["bufferView"] = view;
  expect_untextured(expect_loaded(write("view.glb", b.glb())), {"runs past the end of its buffer"});
}

// ---------------------------------------------------------- extensions ---

TEST_F(BadInput, RequiredExtensionNotSupported) {
  GltfBuilder b;
  b.one_triangle();
  b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  expect_refused(write_gltf("draco", b), {"requires the extension KHR_draco_mesh_compression", "not supported"});
  // Used but not required: the file carries a fallback, and loads.
  b.doc.erase("extensionsRequired");
  expect_loaded(write_gltf("draco_optional", b));
  // A required extension the IG does honour.
  b.doc["extensionsRequired"] = {"KHR_materials_unlit"};
  expect_loaded(write_gltf("unlit", b));
}

// ----------------------------------------------------------- hierarchy ---

TEST_F(BadInput, NodeLoopsAndTwoParents) {
  GltfBuilder loop;
  loop.one_triangle();                 // node 0
  loop.add_node("a", -1, {2});          // node 1 -> 2
  loop.add_node("b", -1, {3});          // node 2 -> 3
  loop.add_node("c", -1, {1});          // node 3 -> 1: a loop, not under any scene root
  expect_refused(write_gltf("loop", loop), {"node hierarchy loop", "node 1 ('a')", "node 3 ('c')"});

  GltfBuilder self;
  self.one_triangle();
  self.doc["nodes"][0]["children"] = {0};
  expect_refused(write_gltf("self", self), {"node hierarchy loop", "node 0 ('tri') is its own child"});

  GltfBuilder two;
  two.one_triangle();                   // node 0, the mesh
  two.add_node("left", -1, {0});         // node 1
  two.add_node("right", -1, {0});        // node 2
  two.set_scene({1, 2});
  expect_refused(write_gltf("two_parents", two), {"node 0 ('tri') has two parents", "node 1 ('left')", "node 2 ('right')"});

  GltfBuilder missing;
  missing.one_triangle();
  missing.doc["nodes"][0]["children"] = {42};
  expect_refused(write_gltf("missing_child", missing), {"lists child 42, which does not exist"});
}

TEST_F(BadInput, NonFiniteTransform) {
  GltfBuilder b;
  b.one_triangle();
  b.doc["nodes"][0]["scale"] = {1.0, 1e300, 1.0};  // finite in JSON, infinite as a float: caught in the bounds
  expect_refused(write_gltf("scale", b), {"extent is not finite"});
}

TEST_F(BadInput, MissingDefaultScene) {
  GltfBuilder b;
  b.one_triangle();
  b.doc["scene"] = 5;
  ModelLoad r = expect_loaded(write_gltf("scene5", b));
  EXPECT_TRUE(any_warning(r, {"default scene 5 does not exist", "drawing scene 0"}));
  b.doc.erase("scenes");
  b.doc.erase("scene");
  b.add_node("second_root", 0);
  r = expect_loaded(write_gltf("noscene", b));
  EXPECT_TRUE(any_warning(r, {"no scene: drawing all 2 root nodes"}));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.model->triangles, 2u);
}

// ------------------------------------------------------------ primitives ---

TEST_F(BadInput, PointsAndLines) {
  GltfBuilder b;
  const int pos = b.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int tri = b.add_mesh(pos, -1, kTriangles);
  const int points = b.add_mesh(pos, -1, kPoints, -1, "dots");
  const int lines = b.add_mesh(pos, -1, kLines, -1, "edges");
  b.set_scene({b.add_node("t", tri), b.add_node("p", points), b.add_node("l", lines)});
  const ModelLoad r = expect_loaded(write_gltf("mixed", b));
  EXPECT_TRUE(any_warning(r, {"mesh 1 ('dots') primitive 0: points (mode 0) skipped"}));
  EXPECT_TRUE(any_warning(r, {"mesh 2 ('edges') primitive 0: lines (mode 1) skipped"}));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.model->triangles, 1u);
  // Only points: nothing to draw.
  b.set_scene({1});
  expect_refused(write_gltf("points", b), {"nothing to draw", "1 of them points, lines or empty"});
}

// ------------------------------------------------------------ triangles ---

// One 1000-triangle mesh drawn by 10 001 nodes: 10 001 000 triangles from a
// file of a few hundred kilobytes, refused before any vertex is read.
TEST_F(BadInput, InstancedPastTheTriangleCap) {
  GltfBuilder b;
  const int pos = b.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3");
  std::vector<std::uint32_t> idx;
  for (int t = 0; t < 1000; ++t) idx.insert(idx.end(), {0u, 1u, std::uint32_t(2 + t % 2)});
  const int mesh = b.add_mesh(pos, b.add_indices(idx), kTriangles, -1, "grid");
  std::vector<int> children;
  for (int i = 0; i < 10001; ++i) children.push_back(b.add_node("", mesh));
  b.set_scene({b.add_node("root", -1, children)});
  expect_refused(write_gltf("instanced", b),
                 {"10001000 triangles counting instancing, above the cap of 1000000",
                  "mesh 0 ('grid'): 1000 triangles drawn by 10001 nodes"});
}

TEST_F(BadInput, SmallTriangleCap) {
  const std::uint64_t n = 1476;  // designs::aircraft_triangles(Fine), checked in entity_models_test
  ModelLimits limits;
  limits.max_triangles = n - 1;
  expect_refused(kAircraft, {std::to_string(n) + " triangles counting instancing, above the cap of " + std::to_string(n - 1)},
                 limits);
  limits.max_triangles = n;  // exactly at the cap: loads
  const ModelLoad r = expect_loaded(kAircraft, limits);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.model->triangles, n);
}

TEST_F(BadInput, FileSizeCap) {
  ModelLimits limits;
  limits.max_file_bytes = 1000;
  expect_refused(kAircraft, {"above the cap of 1000"}, limits);
}

}  // namespace
