#pragma once
// Line-oriented reading of small text geometry files (.gen, .xyz) with errors that name the
// file and the line. Numbers are parsed strictly: the whole token must be a finite number.
#include <istream>
#include <string>
#include <vector>

namespace mesochain::objective::detail {

struct TextLine {
  int number = 0;                   // 1-based line number in the file (0: end of file)
  std::string text;                 // the raw line (without the line break)
  std::vector<std::string> tokens;  // whitespace-separated fields
};

class TextReader {
 public:
  // Reads the whole stream; `source` names it in errors (usually the file path).
  TextReader(std::string source, std::istream& in);
  // Opens `path`; a missing or unreadable file is an InputError naming it.
  static TextReader open(const std::string& path);

  const std::string& source() const { return source_; }
  // Lines not yet read.
  std::size_t remaining() const { return lines_.size() - cursor_; }
  // The next line as it is (possibly blank); false at the end of the input.
  bool nextRaw(TextLine& line);
  // The next line that is not blank (and, when skipHashComments, does not start with '#').
  bool next(TextLine& line, bool skipHashComments);
  // Like next(), but the end of the input is an InputError saying `what` was expected.
  TextLine expect(const std::string& what, bool skipHashComments);
  // Throws when a non-blank line (or a non-comment line) remains.
  void expectEnd(const std::string& what, bool skipHashComments);

  // Errors at a line: "file, line N: found ...; expected ...".
  [[noreturn]] void fail(const TextLine& line, const std::string& found,
                         const std::string& expected) const;
  // Field `index` (0-based) of the line as a finite real number / an integer.
  double real(const TextLine& line, std::size_t index, const std::string& what) const;
  long integer(const TextLine& line, std::size_t index, const std::string& what) const;
  // Field `index` as the atom count of a structure file: an integer from 1 to 10^8.
  long atomCount(const TextLine& line, std::size_t index) const;
  // Throws unless the line has exactly `count` fields (or at least `count` when !exact).
  void requireFields(const TextLine& line, std::size_t count, const std::string& what,
                     bool exact = true) const;

 private:
  std::string source_;
  std::vector<std::string> lines_;
  std::size_t cursor_ = 0;
};

// Splits on blanks and tabs.
std::vector<std::string> splitFields(const std::string& text);
// Strict conversions: true when the whole token is a number (a Fortran 'D' exponent is
// accepted for reals).
bool parseReal(const std::string& token, double& value);
bool parseInteger(const std::string& token, long& value);
// An element symbol: an upper-case letter and up to two lower-case letters (C, Si, Uue).
bool isElementName(const std::string& s);

}  // namespace mesochain::objective::detail
