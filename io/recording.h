#pragma once
// Recording of received datagrams, for deterministic replay through the same
// decoders and filter (`ig serve --record FILE`, `ig run --recording FILE`).
//
// File format (little-endian): the 8 bytes "IGREC1\n\0", then records of
//   f64 receive time (IG steady clock, seconds) | u8 protocol | u16 length | bytes.
// A truncated last record (the IG killed mid-write) is ignored on reading.

#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/pose_intake.h"

namespace ig::io {

struct RecordingError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RecordedDatagram {
  double receive_time_s = 0.0;
  Protocol protocol = Protocol::Native;
  std::vector<std::uint8_t> bytes;
};

class RecordingWriter {
 public:
  explicit RecordingWriter(const std::string& path);  // throws RecordingError
  void write(Protocol protocol, std::span<const std::uint8_t> datagram, double receive_time_s);
  std::uint64_t count() const { return count_; }

 private:
  std::string path_;
  std::ofstream out_;
  std::uint64_t count_ = 0;
};

// Reads the whole file; throws RecordingError naming the file and the problem
// (missing, not a recording, bad protocol byte).
std::vector<RecordedDatagram> read_recording(const std::string& path);

}  // namespace ig::io
