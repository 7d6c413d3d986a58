// libFuzzer target: the STL reader on arbitrary bytes. See fuzz/README.md.
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return delpsc::fuzz::read_one(data, size, delpsc::io::ModelFormat::stl);
}
