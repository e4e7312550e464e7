// Fuzz target: the objective-cell TOML reader (input/cell_file.hpp), geometry files and
// parameter sets included as the file names them (relative to the scratch folder or params/).
#include "fuzz/fuzz_input.hpp"
#include "input/cell_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = mesochain::fuzz::writeScratch(data, size, ".toml");
  mesochain::fuzz::expectCleanRefusal([&] { mesochain::objective::readCellFile(path); });
  return 0;
}
