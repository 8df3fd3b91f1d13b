#include "models/glb_container.h"

#include <cstring>

#include "models/model_error.h"

namespace ig::models {

namespace {

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

// GLB is little-endian whatever the host.
std::uint32_t read_u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
         std::uint32_t(b[at + 3]) << 24;
}

void write_u32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + std::size_t(i)] = std::uint8_t(v >> (8 * i));
}

std::string chunk_type_text(std::uint32_t type) {
  std::string s;
  for (int i = 0; i < 4; ++i) {
    const char c = char(type >> (8 * i));
    if (c == '\0') break;  // "BIN\0"
    s += (c >= 32 && c < 127) ? c : '?';
  }
  return s;
}

}  // namespace

bool is_glb(const std::vector<std::uint8_t>& bytes) {
  return bytes.size() >= 4 && read_u32(bytes, 0) == kMagic;
}

GlbLayout check_glb(std::vector<std::uint8_t>& bytes) {
  const std::size_t size = bytes.size();
  if (size < 12) {
    throw ModelError("truncated glTF binary: " + std::to_string(size) + " bytes, shorter than the 12-byte header");
  }
  const std::uint32_t version = read_u32(bytes, 4);
  if (version != 2) {
    throw ModelError("glTF binary version " + std::to_string(version) + " is not supported (only version 2)");
  }
  const std::uint32_t length = read_u32(bytes, 8);
  if (length > size) {
    throw ModelError("truncated glTF binary: the header says " + std::to_string(length) + " bytes, the file has " +
                     std::to_string(size));
  }
  GlbLayout layout;
  if (length < size) {
    layout.notes.push_back(std::to_string(size - length) + " bytes after the glTF binary's declared end ignored");
  }
  if (length < 20) throw ModelError("glTF binary without a JSON chunk (" + std::to_string(length) + " bytes)");

  // Chunk 0: JSON. Offsets are 64-bit so no length field can wrap them.
  const std::uint64_t json_len = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != kChunkJson) {
    throw ModelError("glTF binary's first chunk is '" + chunk_type_text(read_u32(bytes, 16)) + "', not JSON");
  }
  if (json_len == 0) throw ModelError("glTF binary's JSON chunk is empty");
  const std::uint64_t json_end = 20 + json_len;
  if (json_end > length) {
    throw ModelError("truncated glTF binary: the JSON chunk claims " + std::to_string(json_len) + " bytes, " +
                     std::to_string(length - 20) + " remain");
  }
  layout.json = std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20, std::size_t(json_len));
  layout.used_bytes = std::size_t(json_end);

  // Chunk 1, if any: BIN (the spec allows it only second). Later chunks, or a
  // second chunk of another type, are extensions' business and ignored.
  std::uint64_t at = json_end;
  bool first_after_json = true;
  while (at < length) {
    if (at + 8 > length) {
      throw ModelError("truncated glTF binary: a chunk header at byte " + std::to_string(at) + " is cut off");
    }
    const std::uint64_t chunk_len = read_u32(bytes, std::size_t(at));
    const std::uint32_t type = read_u32(bytes, std::size_t(at) + 4);
    if (at + 8 + chunk_len > length) {
      throw ModelError("truncated glTF binary: the " + chunk_type_text(type) + " chunk at byte " + std::to_string(at) +
                       " claims " + std::to_string(chunk_len) + " bytes, " + std::to_string(length - at - 8) +
                       " remain");
    }
    if (type == kChunkBin && first_after_json) {
      if (chunk_len % 4 != 0 || chunk_len == 0) {
        throw ModelError("glTF binary's BIN chunk is " + std::to_string(chunk_len) +
                         " bytes, not a positive multiple of 4");
      }
      layout.bin_bytes = std::size_t(chunk_len);
      layout.used_bytes = std::size_t(at + 8 + chunk_len);
    } else {
      layout.notes.push_back("glTF binary chunk '" + chunk_type_text(type) + "' at byte " + std::to_string(at) +
                             " ignored");
    }
    first_after_json = false;
    at += 8 + chunk_len;
  }
  // TinyGLTF reads up to the header's length: make that the chunks it may use.
  write_u32(bytes, 8, std::uint32_t(layout.used_bytes));
  return layout;
}

}  // namespace ig::models
