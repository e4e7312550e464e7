// main() of a fuzz target without libFuzzer (any compiler): runs every file named on the command
// line, or every file of every folder named, through LLVMFuzzerTestOneInput once. The test suite
// replays the seed corpus this way (a smoke run); docs/fuzzing.md gives the libFuzzer long run.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {
void runFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}
}  // namespace

int main(int argc, char** argv) {
  int files = 0;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path p(argv[i]);
    if (std::filesystem::is_directory(p)) {
      for (const auto& e : std::filesystem::recursive_directory_iterator(p))
        if (e.is_regular_file()) runFile(e.path()), ++files;
    } else {
      runFile(p), ++files;
    }
  }
  std::printf("replayed %d inputs without a finding\n", files);
  return files > 0 ? 0 : 1;
}
