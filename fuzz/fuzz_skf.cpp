// Fuzz target: the .skf reader (dftb/skf_file.hpp), homonuclear or not by the first byte.
#include "dftb/skf_file.hpp"
#include "fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool homonuclear = size > 0 && (data[0] & 1) == 0;
  const std::string path = mesochain::fuzz::writeScratch(data, size, ".skf");
  mesochain::fuzz::expectCleanRefusal([&] { mesochain::dftb::readSkfFile(path, homonuclear); });
  return 0;
}
