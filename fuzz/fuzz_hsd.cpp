// Fuzz target: the DFTB+ input reader (input/hsd/dftb_input.hpp: the HSD parser and its mapping
// onto the cell settings), includes and .gen geometries as the input names them.
#include "fuzz/fuzz_input.hpp"
#include "input/hsd/dftb_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = mesochain::fuzz::writeScratch(data, size, ".hsd");
  mesochain::fuzz::expectCleanRefusal([&] { mesochain::input::hsd::readDftbInput(path); });
  return 0;
}
