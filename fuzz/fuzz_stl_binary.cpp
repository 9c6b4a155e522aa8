// libFuzzer target: binary STL. The first byte picks the framing, the rest are facet records:
// for 7 of 8 values the harness writes an 80-byte header (starting "solid" when bit 3 is set, as
// some exporters write) and the facet count, and pads the records with zeros to 50 bytes each, so
// the file always has the binary size 84 + 50 n and the binary reader runs; for the 8th (low three
// bits all set) the rest goes to the reader as it is (a truncated file, a wrong count). Bits 4 and 5
// pick the object's options (stl_common.hpp). A SceneError is the expected answer; anything else is
// a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_util.hpp"
#include "stl_common.hpp"

namespace {

constexpr std::size_t kHeader = 80, kRecord = 50;

std::string framed(const std::string& records, bool solid_header) {
  const std::size_t n = (records.size() + kRecord - 1) / kRecord;
  std::string out(kHeader, '\0');
  if (solid_header) out.replace(0, 11, "solid fuzz ");
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((n >> (8 * k)) & 0xff));
  out += records;
  out.resize(kHeader + 4 + kRecord * n, '\0');
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t mode = data[0];
  const std::string rest = watkins::fuzz::bytes_of(data + 1, size - 1);
  watkins::fuzz::read_stl((mode & 7) == 7 ? rest : framed(rest, (mode & 8) != 0), (mode >> 4) & 3u);
  return 0;
}
