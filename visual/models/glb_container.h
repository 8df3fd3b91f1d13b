#pragma once
// The binary glTF container (.glb: a 12-byte header, a JSON chunk, an
// optional BIN chunk), checked before TinyGLTF parses it.
//
// Why our own check: TinyGLTF 2.7.0 trusts the BIN chunk's length field by
// 8 bytes too much (it compares the chunk's payload, not payload + header,
// with the file's length), so a file whose last chunk claims to run to the
// end of the file would be read past its end. Here every length is checked
// against the bytes actually read, and the header is rewritten so TinyGLTF
// only ever sees the JSON chunk and the BIN chunk that follows it (chunks of
// other types are ignored, as the spec asks).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ig::models {

// True when `bytes` starts with the GLB magic "glTF".
bool is_glb(const std::vector<std::uint8_t>& bytes);

struct GlbLayout {
  std::string_view json;         // the JSON chunk's text (points into the bytes)
  std::size_t bin_bytes = 0;     // the BIN chunk's payload; 0: none
  std::size_t used_bytes = 0;    // header + JSON chunk + BIN chunk: what TinyGLTF gets
  std::vector<std::string> notes;  // what was ignored (trailing bytes, unknown chunks)
};

// Checks the container and rewrites its length field to used_bytes. Throws
// ModelError with the fault: truncated, bad version, bad chunk lengths...
GlbLayout check_glb(std::vector<std::uint8_t>& bytes);

}  // namespace ig::models
