#pragma once
// Append-only text outputs of a run (CSV time series, XYZ trajectories) that a kill cannot leave
// half-written: every record (a CSV row, an XYZ frame) goes to the file in one write and is
// flushed, so the file always ends at a record boundary (a cut-off last line cannot look like
// data). A resumed run reopens the file, cuts it back to the length it had at the checkpoint
// (dropping rows written after it) and appends: no duplicated or missing rows.
#include <cstdint>
#include <cstdio>
#include <string>

namespace mesochain::mdem {

class AppendFile {
 public:
  // A new file (truncated), or, with resumeAt >= 0, the existing file cut back to resumeAt bytes.
  // InputError naming the path when it cannot be opened, or is shorter than resumeAt.
  AppendFile(const std::string& path, std::int64_t resumeAt = -1);
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  // Writes one record in one call and flushes it.
  void write(const std::string& record);
  // Bytes written so far (the file's length): what a checkpoint stores.
  std::int64_t bytes() const { return bytes_; }
  const std::string& path() const { return path_; }
  bool resumed() const { return resumed_; }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::int64_t bytes_ = 0;
  bool resumed_ = false;
};

}  // namespace mesochain::mdem
