// Fuzz target: the DFTB+ .gen reader (input/gen_file.hpp).
#include "fuzz/fuzz_input.hpp"
#include "input/gen_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = mesochain::fuzz::writeScratch(data, size, ".gen");
  mesochain::fuzz::expectCleanRefusal([&] { mesochain::objective::readGenFile(path); });
  return 0;
}
