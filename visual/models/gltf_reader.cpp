#include "models/gltf_reader.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>

#include <nlohmann/json.hpp>

#include "models/glb_container.h"
#include "models/model_error.h"

namespace ig::models {

namespace fs = std::filesystem;

namespace {

// --------------------------------------------------------------- files ---

// Reads a whole file of at most max_bytes; false with the reason otherwise.
bool read_capped(const std::string& path, std::uint64_t max_bytes, std::vector<std::uint8_t>& out,
                 std::string& why) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) {
    why = "no such file";
    return false;
  }
  if (fs::is_directory(st)) {
    why = "is a folder, not a file";
    return false;
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) {
    why = "cannot be read (" + ec.message() + ")";
    return false;
  }
  if (size > max_bytes) {
    why = std::to_string(size) + " bytes, above the cap of " + std::to_string(max_bytes);
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = std::string("cannot be opened (") + std::strerror(errno) + ")";
    return false;
  }
  out.resize(std::size_t(size));
  in.read(reinterpret_cast<char*>(out.data()), std::streamsize(size));
  if (std::uint64_t(in.gcount()) != size) {
    why = "cannot be read to its end (" + std::to_string(in.gcount()) + " of " + std::to_string(size) + " bytes)";
    return false;
  }
  return true;
}

// TinyGLTF's file callbacks. It looks for a uri in the model's folder and
// then in the working directory; base_dir is absolute, so only candidates
// under it are accepted, never the working directory's.
struct FileAccess {
  std::string base_dir;  // absolute, no trailing slash
  std::uint64_t max_bytes = 0;
};

bool file_exists_cb(const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  if (path.compare(0, access->base_dir.size(), access->base_dir) != 0) return false;
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

std::string expand_path_cb(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool read_file_cb(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  std::string why;
  if (read_capped(path, access->max_bytes, *out, why)) return true;
  if (err) *err += why;
  return false;
}

// -------------------------------------------------------------- images ---

struct ImageContext {
  const ModelLimits* limits = nullptr;
  tinygltf::Model* target = nullptr;  // the model TinyGLTF is filling (buffer views are read by then)
  std::uint64_t pixels = 0;           // decoded so far
  std::map<int, std::string> failures;
};

std::uint32_t be32(const unsigned char* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}
std::uint32_t be16(const unsigned char* p) { return std::uint32_t(p[0]) << 8 | p[1]; }

// Width and height from a PNG's or JPEG's header, without decoding; false
// with the reason when the bytes are neither (glTF allows only those two).
bool image_size(const unsigned char* b, std::size_t n, std::uint32_t& w, std::uint32_t& h, std::string& why) {
  static const unsigned char png[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  if (n >= 8 && std::memcmp(b, png, 8) == 0) {
    if (n < 24 || std::memcmp(b + 12, "IHDR", 4) != 0) {
      why = "PNG without its IHDR header";
      return false;
    }
    w = be32(b + 16);
    h = be32(b + 20);
    return true;
  }
  if (n >= 3 && b[0] == 0xFF && b[1] == 0xD8) {
    // Walk the JPEG's marker segments to the frame header (SOFn).
    std::size_t i = 2;
    while (i + 4 <= n) {
      if (b[i] != 0xFF) break;
      const unsigned char marker = b[i + 1];
      if (marker == 0xFF) {  // fill byte
        ++i;
        continue;
      }
      if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) {  // segments without a length
        i += 2;
        continue;
      }
      if (marker == 0xD9 || marker == 0xDA) break;  // end of image / scan data before any frame
      const std::size_t len = be16(b + i + 2);
      if (len < 2) break;
      const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
      if (sof) {
        if (i + 9 > n) break;
        h = be16(b + i + 5);
        w = be16(b + i + 7);
        return true;
      }
      i += 2 + len;
    }
    why = "JPEG without a readable frame header";
    return false;
  }
  why = "neither PNG nor JPEG";
  return false;
}

// TinyGLTF's image callback. Always returns true, so one bad image never
// fails the whole model: the reason is kept and the image left empty.
bool decode_image_cb(tinygltf::Image* image, const int index, std::string*, std::string*, int req_width,
                     int req_height, const unsigned char* bytes, int size, void* user) {
  auto* ctx = static_cast<ImageContext*>(user);
  auto fail = [&](const std::string& why) {
    ctx->failures[index] = why;
    image->image.clear();
    image->width = image->height = 0;
    return true;
  };
  if (image->bufferView >= 0) {
    // TinyGLTF hands over &buffer[byteOffset] without checking the view
    // lies inside its buffer: check before reading a byte.
    const auto& views = ctx->target->bufferViews;
    const auto& buffers = ctx->target->buffers;
    if (std::size_t(image->bufferView) >= views.size()) return fail("its bufferView does not exist");
    const tinygltf::BufferView& view = views[std::size_t(image->bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= buffers.size()) return fail("its bufferView's buffer does not exist");
    const std::size_t buffer_size = buffers[std::size_t(view.buffer)].data.size();
    if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset) {
      return fail("bufferView " + std::to_string(image->bufferView) + " runs past the end of its buffer");
    }
  }
  if (bytes == nullptr || size <= 0) return fail("no image data");
  std::uint32_t w = 0, h = 0;
  std::string why;
  if (!image_size(bytes, std::size_t(size), w, h, why)) return fail(why);
  if (w == 0 || h == 0) return fail("a " + std::to_string(w) + " x " + std::to_string(h) + " image");
  const std::uint64_t pixels = std::uint64_t(w) * h;
  if (ctx->pixels + pixels > ctx->limits->max_texture_pixels) {
    return fail(std::to_string(w) + " x " + std::to_string(h) + " pixels would pass the cap of " +
                std::to_string(ctx->limits->max_texture_pixels) + " texture pixels per model");
  }
  // TinyGLTF's own stb_image decoder. No options (nullptr): it expands
  // every image to 4 channels, RGBA.
  std::string err, warn;
  if (!tinygltf::LoadImageData(image, index, &err, &warn, req_width, req_height, bytes, size, nullptr)) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    return fail(err.empty() ? "cannot be decoded" : err);
  }
  ctx->pixels += pixels;
  return true;
}

// --------------------------------------------------------------- JSON ----

// The deepest array/object nesting in `text`, stopping once past `limit`.
int json_depth(std::string_view text, int limit) {
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) return deepest;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

std::string strip_json_prefix(std::string what) {
  // "[json.exception.parse_error.101] parse error at line 1, ..." -> "parse error at line 1, ..."
  if (!what.empty() && what[0] == '[') {
    const auto close = what.find("] ");
    if (close != std::string::npos) what.erase(0, close + 2);
  }
  return what;
}

// What must hold before TinyGLTF parses: JSON at all, glTF 2, no required
// extension we cannot honour.
void check_json(std::string_view text, bool binary, const ModelLimits& limits) {
  if (json_depth(text, limits.max_json_depth) > limits.max_json_depth) {
    throw ModelError("JSON nested more than " + std::to_string(limits.max_json_depth) + " levels deep");
  }
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    throw ModelError(std::string(binary ? "the glTF binary's JSON chunk is not valid JSON: "
                                        : "neither a glTF binary ('glTF' magic) nor valid glTF JSON: ") +
                     strip_json_prefix(e.what()));
  }
  if (!doc.is_object()) throw ModelError("the glTF JSON is not an object (it is " + std::string(doc.type_name()) + ")");
  const auto asset = doc.find("asset");
  if (asset == doc.end() || !asset->is_object()) throw ModelError("no \"asset\" object: not a glTF 2.0 file");
  const auto version = asset->find("version");
  if (version == asset->end() || !version->is_string()) {
    throw ModelError("\"asset\" has no \"version\" string: not a glTF 2.0 file");
  }
  const std::string v = version->get<std::string>();
  if (v.rfind("2.", 0) != 0) throw ModelError("glTF version \"" + v + "\" is not supported (only 2.x)");

  const auto required = doc.find("extensionsRequired");
  if (required != doc.end() && required->is_array()) {
    const auto& supported = supported_required_extensions();
    for (const auto& e : *required) {
      if (!e.is_string()) continue;
      const std::string name = e.get<std::string>();
      if (std::find(supported.begin(), supported.end(), name) == supported.end()) {
        std::string list;
        for (const auto& s : supported) list += (list.empty() ? "" : ", ") + s;
        throw ModelError("requires the extension " + name + ", which is not supported (supported: " + list + ")");
      }
    }
  }
}

std::string tidy(std::string text) {
  // TinyGLTF's messages end in newlines and may be several: one line.
  std::string out;
  bool space = false;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      space = !out.empty();
      continue;
    }
    if (space) out += "; ";
    space = false;
    out += c;
  }
  return out;
}

}  // namespace

const std::vector<std::string>& supported_required_extensions() {
  // KHR_mesh_quantization: integer attributes, which the accessor reader
  // converts anyway. KHR_materials_unlit: Material::unlit.
  static const std::vector<std::string> names = {"KHR_mesh_quantization", "KHR_materials_unlit"};
  return names;
}

GltfDocument read_gltf(const std::string& path, const ModelLimits& limits, std::vector<std::string>& warnings) {
  std::vector<std::uint8_t> bytes;
  std::string why;
  if (!read_capped(path, limits.max_file_bytes, bytes, why)) throw ModelError(why);
  if (bytes.empty()) throw ModelError("empty file (0 bytes)");
  if (bytes.size() > 0x7FFFFFFFu) throw ModelError("larger than 2 GiB");  // TinyGLTF takes an unsigned int size

  const bool binary = is_glb(bytes);
  std::string_view json;
  std::size_t used = bytes.size();
  if (binary) {
    GlbLayout layout = check_glb(bytes);
    for (const std::string& note : layout.notes) warnings.push_back(note);
    json = layout.json;
    used = layout.used_bytes;
  } else {
    json = std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }
  check_json(json, binary, limits);

  std::error_code ec;
  FileAccess access;
  access.base_dir = fs::absolute(fs::path(path), ec).parent_path().lexically_normal().string();
  while (access.base_dir.size() > 1 && access.base_dir.back() == '/') access.base_dir.pop_back();
  access.max_bytes = limits.max_file_bytes;

  GltfDocument doc;
  ImageContext images;
  images.limits = &limits;
  images.target = &doc.gltf;

  tinygltf::TinyGLTF loader;
  tinygltf::FsCallbacks callbacks{};
  callbacks.FileExists = &file_exists_cb;
  callbacks.ExpandFilePath = &expand_path_cb;
  callbacks.ReadWholeFile = &read_file_cb;
  callbacks.WriteWholeFile = &tinygltf::WriteWholeFile;  // never used: we only read
  callbacks.user_data = &access;
  loader.SetFsCallbacks(callbacks);
  loader.SetImageLoader(&decode_image_cb, &images);

  std::string err, warn;
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&doc.gltf, &err, &warn, bytes.data(), unsigned(used), access.base_dir)
                : loader.LoadASCIIFromString(&doc.gltf, &err, &warn, json.data(), unsigned(json.size()),
                                             access.base_dir);
  } catch (const std::bad_alloc&) {
    throw ModelError("out of memory while parsing");
  } catch (const std::exception& e) {
    throw ModelError(std::string("TinyGLTF failed: ") + e.what());
  }
  if (!ok) throw ModelError("TinyGLTF: " + (err.empty() ? std::string("cannot parse the file") : tidy(err)));
  doc.image_failures = std::move(images.failures);
  return doc;
}

}  // namespace ig::models
