#include "common/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <utility>

#include "common/errors.hpp"

namespace mesochain {

namespace fs = std::filesystem;

namespace {
std::string temporaryName(const std::string& path) {
  return path + ".tmp." + std::to_string(::getpid());
}

void renameOver(const std::string& from, const std::string& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) {
    fs::remove(from, ec);
    throw InputError(to, "cannot rename the finished temporary file " + from +
                             " to this output: " + ec.message());
  }
}
}  // namespace

bool isStandardOutput(const std::string& path) { return path == "-"; }

namespace {
bool fileOutput = true;
}  // namespace
void setFileOutputEnabled(bool enabled) { fileOutput = enabled; }
bool fileOutputEnabled() { return fileOutput; }

AtomicOutputFile::AtomicOutputFile(std::string path)
    : path_(std::move(path)), temporary_(isStandardOutput(path_) ? std::string() : temporaryName(path_)) {
  if (!fileOutput && !isStandardOutput(path_)) {
    discarded_ = true;
    temporary_ = "/dev/null";
    stream_.open(temporary_, std::ios::binary);
    return;
  }
  if (isStandardOutput(path_)) {
    // "-": the standard output, written directly (appending, so nothing already written to it
    // is truncated; the caller sends its own messages to stderr).
    std::cout.flush();
    stream_.open("/dev/stdout", std::ios::binary | std::ios::app);
    if (!stream_) throw InputError(path_, std::string("cannot write to the standard output: ") + std::strerror(errno));
    return;
  }
  stream_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!stream_)
    throw InputError(path_, "cannot create the output file (temporary " + temporary_ +
                                "): " + std::strerror(errno));
}

AtomicOutputFile::~AtomicOutputFile() {
  if (committed_ || discarded_) return;
  stream_.close();
  if (temporary_.empty()) return;
  std::error_code ec;
  fs::remove(temporary_, ec);
}

void AtomicOutputFile::commit() {
  if (discarded_) {
    stream_.close();
    committed_ = true;
    return;
  }
  bool ok = true;
  if (stream_.is_open()) {  // (closed already when a C library wrote temporaryPath())
    stream_.flush();
    ok = static_cast<bool>(stream_);
    stream_.close();
    ok = ok && !stream_.fail();
  }
  if (!ok) {
    std::error_code ec;
    fs::remove(temporary_, ec);
    throw InputError(path_, "writing the output file failed (disk full?)");
  }
  if (!temporary_.empty()) renameOver(temporary_, path_);
  committed_ = true;
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  AtomicOutputFile out(path);
  out.stream() << text;
  out.commit();
}

void requireWritableOutput(const std::string& path, const std::string& source,
                           const std::string& where) {
  if (path.empty())
    throw InputError(source, where, "an empty path", "the path of a file to write");
  if (isStandardOutput(path)) return;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw InputError(source, where, "\"" + path + "\", which is a folder",
                     "the path of a file to write");
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (!fs::is_directory(folder, ec))
    throw InputError(source, where,
                     "\"" + path + "\", whose folder " + folder.string() + " does not exist",
                     "a file in an existing folder");
  if (::access(folder.c_str(), W_OK) != 0)
    throw InputError(source, where,
                     "\"" + path + "\", whose folder " + folder.string() + " is not writable",
                     "a file in a writable folder");
}

}  // namespace mesochain
