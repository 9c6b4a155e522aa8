// libFuzzer target: the input as an STL file's bytes, as they are (scripts/fuzz seeds it with ASCII
// files, so most executions take the ASCII reader; a size of 84 + 50 n reaches the binary one). A
// SceneError is the expected answer to bad input; any other exception, a crash or a sanitizer
// report is a finding. The input's size picks the object's options (stl_common.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_util.hpp"
#include "stl_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  watkins::fuzz::read_stl(watkins::fuzz::bytes_of(data, size), static_cast<unsigned>(size % 4));
  return 0;
}
