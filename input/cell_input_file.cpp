#include "input/cell_input_file.hpp"

#include <filesystem>

#include "common/errors.hpp"
#include "common/toml_file.hpp"

#include "input/hsd/dftb_input.hpp"
#include "input/hsd/hsd_tree.hpp"

namespace mesochain::input {

bool isDftbInput(const std::string& path) {
  return hsd::lowerCase(std::filesystem::path(path).extension().string()) == ".hsd";
}

objective::CellInput readCellInputFile(const std::string& path) {
  if (!isDftbInput(path)) return objective::readCellFile(path);
  // --set/--unset override keys of TOML files; silently not applying them would be wrong.
  if (tomlOverridesUnused())
    throw InputError("<command line>", "option --set/--unset", "--set or --unset with the DFTB+ input " + path,
                     "no --set/--unset (they override keys of TOML inputs): edit the .hsd, or `mesochain "
                     "convert` it to a cell file and use --set/--unset on that");
  return hsd::readDftbInput(path);
}

}  // namespace mesochain::input
