#include "io/recording.h"

#include <cstring>
#include <filesystem>

namespace ig::io {
namespace {
constexpr char kMagic[8] = {'I', 'G', 'R', 'E', 'C', '1', '\n', '\0'};

template <typename T>
void put(std::ofstream& out, T v) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));  // the IG runs on little-endian hosts (x86_64, aarch64)
  out.write(reinterpret_cast<const char*>(b), sizeof(T));
}
}  // namespace

RecordingWriter::RecordingWriter(const std::string& path) : path_(path), out_(path, std::ios::binary) {
  if (!out_) throw RecordingError(path + ": cannot create recording");
  out_.write(kMagic, sizeof kMagic);
}

void RecordingWriter::write(Protocol protocol, std::span<const std::uint8_t> d, double t) {
  if (d.size() > 0xFFFF) return;  // larger than any UDP payload we accept
  put(out_, t);
  put(out_, std::uint8_t(protocol));
  put(out_, std::uint16_t(d.size()));
  out_.write(reinterpret_cast<const char*>(d.data()), std::streamsize(d.size()));
  out_.flush();
  ++count_;
}

std::vector<RecordedDatagram> read_recording(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::error_code ec;
    const auto st = std::filesystem::status(path, ec);
    throw RecordingError(path + (st.type() == std::filesystem::file_type::not_found ? ": no such file"
                                 : st.type() == std::filesystem::file_type::directory ? ": is a folder, not a recording"
                                                                                       : ": cannot open recording"));
  }
  char magic[8] = {};
  in.read(magic, sizeof magic);
  if (in.gcount() != sizeof magic || std::memcmp(magic, kMagic, sizeof magic) != 0)
    throw RecordingError(path + ": not an IG recording (bad header)");
  std::vector<RecordedDatagram> out;
  for (;;) {
    unsigned char head[11];
    in.read(reinterpret_cast<char*>(head), sizeof head);
    if (in.gcount() != sizeof head) break;
    RecordedDatagram r;
    std::memcpy(&r.receive_time_s, head, 8);
    const std::uint8_t proto = head[8];
    std::uint16_t len = 0;
    std::memcpy(&len, head + 9, 2);
    if (proto >= kProtocolCount)
      throw RecordingError(path + ": record " + std::to_string(out.size()) + " has unknown protocol " +
                           std::to_string(proto));
    r.protocol = Protocol(proto);
    r.bytes.resize(len);
    in.read(reinterpret_cast<char*>(r.bytes.data()), len);
    if (in.gcount() != len) break;  // truncated tail
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace ig::io
