#pragma once
// The shared harness of the parser fuzz targets (docs/fuzzing.md): the parsers read files, so an
// input is written to a scratch file (one per process) and parsed from there. A parser may
// refuse any input with InputError (its job) or NumericalError; anything else (another
// exception, a crash, a sanitizer report, a hang) is a bug that the fuzzer reports.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/errors.hpp"

namespace mesochain::fuzz {

// A scratch file with `extension` holding the input bytes.
inline std::string writeScratch(const std::uint8_t* data, std::size_t size,
                                const std::string& extension) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("mesochain-fuzz-" + std::to_string(::getpid()) + extension))
                               .string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

// Runs `parse` and aborts (a finding) on anything but a clean return or an InputError /
// NumericalError.
template <class F>
void expectCleanRefusal(F&& parse) {
  try {
    parse();
  } catch (const InputError&) {
  } catch (const NumericalError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz finding: unexpected exception: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz finding: unexpected non-std exception\n");
    std::abort();
  }
}

}  // namespace mesochain::fuzz
