#pragma once
// Output files written atomically: the text goes to a temporary file in the same folder
// (PATH.tmp.PID), is flushed and closed, and is then renamed over PATH (rename(2) within one
// file system replaces the name in one step). A kill at any moment leaves either no file or the
// previous one, plus possibly a stray PATH.tmp.PID, never a half-written file under PATH.
#include <fstream>
#include <string>

namespace mesochain {

// "-" names the standard output wherever a command writes one file result (`run --json -`,
// `build ... -o -`, `bench kpoints --csv -`); writeFileAtomically and AtomicOutputFile then write
// to stdout directly, and requireWritableOutput accepts it. (A file named "-" is ./-.)
bool isStandardOutput(const std::string& path);

// Whether this process writes output files (default true). Under mpirun the ranks other than 0
// switch it off (app/main.cpp): every rank runs the same code, rank 0 alone writes. Switched
// off, writeFileAtomically and AtomicOutputFile write to /dev/null and create nothing.
void setFileOutputEnabled(bool enabled);
bool fileOutputEnabled();

// Writes `text` to `path` atomically. InputError naming `path` when the temporary file cannot
// be created or written (folder missing, not writable, disk full) or the rename fails.
void writeFileAtomically(const std::string& path, const std::string& text);

// A stream to a temporary file that becomes `path` on commit(); destroyed without commit (an
// exception while writing), the temporary file is removed and `path` left as it was.
//   AtomicOutputFile out(path);
//   out.stream() << ...;
//   out.commit();
class AtomicOutputFile {
 public:
  explicit AtomicOutputFile(std::string path);
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;
  ~AtomicOutputFile();
  std::ofstream& stream() { return stream_; }
  // The temporary file's name: for writers that need a path (C libraries such as libpng).
  const std::string& temporaryPath() const { return temporary_; }
  // Flushes, closes and renames; InputError naming the path when any step fails.
  void commit();

 private:
  std::string path_;
  std::string temporary_;
  std::ofstream stream_;
  bool committed_ = false;
  bool discarded_ = false;  // file output switched off: the stream goes to /dev/null
};

// Checks before a computation that an output can be created at `path`: its folder exists and is
// writable, and `path` is not a folder. InputError(source, where, ...) otherwise, e.g.
// requireWritableOutput("/nonexistent/x.json", "<command line>", "option --json").
void requireWritableOutput(const std::string& path, const std::string& source,
                           const std::string& where);

}  // namespace mesochain
