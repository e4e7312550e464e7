// Fuzz target: the extended-XYZ reader (input/xyz_file.hpp).
#include "fuzz/fuzz_input.hpp"
#include "input/xyz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = mesochain::fuzz::writeScratch(data, size, ".xyz");
  mesochain::fuzz::expectCleanRefusal([&] { mesochain::objective::readXyzFile(path); });
  return 0;
}
