#include "input/text_reader.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::objective::detail {

std::vector<std::string> splitFields(const std::string& text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != '\r') ++j;
    if (j > i) out.push_back(text.substr(i, j - i));
    i = j;
  }
  return out;
}

bool parseReal(const std::string& token, double& value) {
  if (token.empty()) return false;
  std::string t = token;
  for (char& c : t)
    if (c == 'D' || c == 'd') c = 'E';
  const char* begin = t.data();
  if (*begin == '+') ++begin;  // from_chars rejects a leading '+'
  const char* end = t.data() + t.size();
  const auto r = std::from_chars(begin, end, value);
  return r.ec == std::errc() && r.ptr == end;
}

bool parseInteger(const std::string& token, long& value) {
  if (token.empty()) return false;
  const char* begin = token.data();
  if (*begin == '+') ++begin;
  const char* end = token.data() + token.size();
  const auto r = std::from_chars(begin, end, value);
  return r.ec == std::errc() && r.ptr == end;
}

bool isElementName(const std::string& s) {
  if (s.empty() || s.size() > 3 || !std::isupper(static_cast<unsigned char>(s[0]))) return false;
  for (std::size_t k = 1; k < s.size(); ++k)
    if (!std::islower(static_cast<unsigned char>(s[k]))) return false;
  return true;
}

TextReader::TextReader(std::string source, std::istream& in) : source_(std::move(source)) {
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines_.push_back(line);
  }
}

TextReader TextReader::open(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "the file cannot be opened (does it exist?)");
  return TextReader(path, in);
}

bool TextReader::nextRaw(TextLine& line) {
  if (cursor_ >= lines_.size()) return false;
  line.number = static_cast<int>(cursor_ + 1);
  line.text = lines_[cursor_++];
  line.tokens = splitFields(line.text);
  return true;
}

bool TextReader::next(TextLine& line, bool skipHashComments) {
  while (nextRaw(line)) {
    if (line.tokens.empty()) continue;
    if (skipHashComments && line.tokens.front().front() == '#') continue;
    return true;
  }
  return false;
}

TextLine TextReader::expect(const std::string& what, bool skipHashComments) {
  TextLine line;
  if (!next(line, skipHashComments))
    throw InputError(source_, fmt::format("line {}", lines_.size() + 1), "the end of the file",
                     what);
  return line;
}

void TextReader::expectEnd(const std::string& what, bool skipHashComments) {
  TextLine line;
  if (next(line, skipHashComments))
    fail(line, fmt::format("superfluous data '{}'", line.text), what);
}

void TextReader::fail(const TextLine& line, const std::string& found,
                      const std::string& expected) const {
  throw InputError(source_, fmt::format("line {}", line.number), found, expected);
}

double TextReader::real(const TextLine& line, std::size_t index, const std::string& what) const {
  if (index >= line.tokens.size()) fail(line, "too few fields", what);
  double v = 0.0;
  if (!parseReal(line.tokens[index], v)) fail(line, fmt::format("'{}'", line.tokens[index]), what);
  if (!std::isfinite(v)) fail(line, fmt::format("'{}' (not finite)", line.tokens[index]), what);
  return v;
}

long TextReader::integer(const TextLine& line, std::size_t index, const std::string& what) const {
  if (index >= line.tokens.size()) fail(line, "too few fields", what);
  long v = 0;
  if (!parseInteger(line.tokens[index], v))
    fail(line, fmt::format("'{}'", line.tokens[index]), what);
  return v;
}

long TextReader::atomCount(const TextLine& line, std::size_t index) const {
  const long n = integer(line, index, "a number of atoms from 1 to 100000000");
  if (n < 1 || n > 100000000L)
    fail(line, std::to_string(n) + " atoms", "a number of atoms from 1 to 100000000");
  return n;
}

void TextReader::requireFields(const TextLine& line, std::size_t count, const std::string& what,
                               bool exact) const {
  const std::size_t n = line.tokens.size();
  if (n < count || (exact && n != count))
    fail(line, fmt::format("{} field{} ('{}')", n, n == 1 ? "" : "s", line.text),
         fmt::format("{}{} fields: {}", exact ? "" : "at least ", count, what));
}

}  // namespace mesochain::objective::detail
