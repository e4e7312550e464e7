#include "mdem/append_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::mdem {

AppendFile::AppendFile(const std::string& path, std::int64_t resumeAt) : path_(path) {
  if (resumeAt >= 0) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || static_cast<std::int64_t>(size) < resumeAt)
      throw InputError(path, "", ec ? "no file to resume (" + ec.message() + ")" : fmt::format("{} bytes", size),
                       fmt::format("the output of the interrupted run, at least {} bytes long (the checkpoint's)", resumeAt));
    std::filesystem::resize_file(path, resumeAt, ec);
    if (ec) throw InputError(path, "cannot cut the output back to the checkpoint: " + ec.message());
    file_ = std::fopen(path.c_str(), "ab");
    bytes_ = resumeAt;
    resumed_ = true;
  } else {
    file_ = std::fopen(path.c_str(), "wb");
  }
  if (!file_) throw InputError(path, "", std::string("a file that cannot be written: ") + std::strerror(errno), "a writable path");
}

AppendFile::~AppendFile() {
  if (file_) std::fclose(file_);
}

void AppendFile::write(const std::string& record) {
  if (std::fwrite(record.data(), 1, record.size(), file_) != record.size() || std::fflush(file_) != 0)
    throw InputError(path_, std::string("writing the output failed (disk full?): ") + std::strerror(errno));
  bytes_ += static_cast<std::int64_t>(record.size());
}

}  // namespace mesochain::mdem
