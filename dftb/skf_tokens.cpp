#include "dftb/skf_tokens.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include "common/errors.hpp"

namespace mesochain::dftb {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Splits a line into value tokens. A comma separates values like blanks do, but two commas with
// only blanks between them (or a comma opening the line) would be a Fortran null value: refused.
std::vector<std::string> tokens(const SkfLine& line) {
  std::vector<std::string> out;
  const std::string& s = line.text;
  bool commaSinceValue = true;  // treat the line start like a comma: a leading comma is a null
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (isBlank(c)) {
      ++i;
    } else if (c == ',') {
      if (commaSinceValue) skfError(line, "an empty value before a comma", "a number");
      commaSinceValue = true;
      ++i;
    } else {
      std::size_t j = i;
      while (j < s.size() && !isBlank(s[j]) && s[j] != ',') ++j;
      out.push_back(s.substr(i, j - i));
      commaSinceValue = false;
      i = j;
    }
  }
  return out;
}

std::string quoted(const std::string& t) { return "'" + t + "'"; }

double parseReal(const SkfLine& line, const std::string& token) {
  std::string t = token;
  for (char& c : t) {
    if (c == 'D' || c == 'd') c = 'e';  // Fortran double-precision exponent
  }
  std::size_t start = (!t.empty() && t[0] == '+') ? 1 : 0;
  // A leading '+' followed by a sign would be accepted by from_chars: refuse it explicitly.
  if (start == 1 && t.size() > 1 && (t[1] == '+' || t[1] == '-')) {
    skfError(line, "the garbled number " + quoted(token), "a real number");
  }
  double x = 0.0;
  const char* first = t.data() + start;
  const char* last = t.data() + t.size();
  const auto [ptr, ec] = std::from_chars(first, last, x);
  if (ec == std::errc::result_out_of_range) {
    skfError(line, "the out-of-range number " + quoted(token), "a finite real number");
  }
  if (ec != std::errc() || ptr != last || first == last) {
    skfError(line, "the garbled number " + quoted(token), "a real number");
  }
  if (!std::isfinite(x)) {
    skfError(line, "the non-finite number " + quoted(token), "a finite real number");
  }
  return x;
}

int parseCount(const SkfLine& line, const std::string& token, const std::string& full) {
  int n = 0;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), n);
  if (ec != std::errc() || ptr != token.data() + token.size() || token.empty() || n < 1) {
    skfError(line, "the repeat " + quoted(full),
             "a positive integer count before '*' (as in 20*1.0)");
  }
  return n;
}

}  // namespace

void skfError(const SkfLine& line, const std::string& found, const std::string& expected) {
  throw InputError(line.file ? *line.file : std::string("<skf>"),
                   "line " + std::to_string(line.number), found, expected);
}

std::vector<double> parseSkfNumbers(const SkfLine& line) {
  std::vector<double> out;
  for (const std::string& tok : tokens(line)) {
    const std::size_t star = tok.find('*');
    if (star == std::string::npos) {
      out.push_back(parseReal(line, tok));
      continue;
    }
    const int count = parseCount(line, tok.substr(0, star), tok);
    const std::string value = tok.substr(star + 1);
    if (value.empty()) {
      skfError(line, "the repeat " + quoted(tok) + " without a value (a Fortran null value)",
               "count*value, as in 9*0.0");
    }
    const double x = parseReal(line, value);
    out.insert(out.end(), static_cast<std::size_t>(count), x);
  }
  return out;
}

int parseSkfInteger(const SkfLine& line, int position, const std::string& what) {
  const std::vector<std::string> t = tokens(line);
  if (position >= static_cast<int>(t.size())) {
    skfError(line, std::to_string(t.size()) + " values", what + " as value " +
                                                              std::to_string(position + 1));
  }
  const std::string& tok = t[static_cast<std::size_t>(position)];
  int n = 0;
  const auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), n);
  if (ec == std::errc::result_out_of_range && ptr == tok.data() + tok.size()) {
    skfError(line, quoted(tok), what + " (an integer of at most 2147483647)");
  }
  if (ec != std::errc() || ptr != tok.data() + tok.size()) {
    skfError(line, quoted(tok), what + " (an integer)");
  }
  return n;
}

}  // namespace mesochain::dftb
