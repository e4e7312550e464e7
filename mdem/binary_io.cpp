#include "mdem/binary_io.hpp"

#include "common/errors.hpp"

namespace mesochain::mdem {

void BinaryReader::expectCount(const std::string& what, std::uint64_t expected) {
  const std::uint64_t n = read<std::uint64_t>();
  if (n != expected)
    throw InputError(source_, "checkpoint section " + what, std::to_string(n) + " entries",
                     std::to_string(expected) + " (the scene's): a checkpoint of another scene");
}

void BinaryReader::fail(const std::string& message) const {
  throw InputError(source_, "checkpoint", message + " at byte " + std::to_string(pos_),
                   "a complete checkpoint written by this scene");
}

}  // namespace mesochain::mdem
