#pragma once
// mesochain::InputError: bad input, reported once by `main` with file, line or key, what was
// found and what was expected. Every parser and constructor that validates user input throws it.
#include <stdexcept>
#include <string>

namespace mesochain {

class InputError : public std::runtime_error {
 public:
  // source: file name (or "<command line>", "<cell>"); where: "line 12" or "key symmetry.twist";
  // found / expected: plain words.
  InputError(std::string source, std::string where, std::string found, std::string expected);
  // A free-form message that still names its source.
  InputError(std::string source, std::string message);

  const std::string& source() const { return source_; }
  const std::string& where() const { return where_; }

 private:
  std::string source_;
  std::string where_;
};

// A numerical failure that is not the user's fault but must not pass silently
// (e.g. an eigensolver that did not converge, a Fermi level that cannot be bracketed).
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws InputError when x is not finite; `what` names the quantity.
void requireFinite(double x, const std::string& source, const std::string& what);

}  // namespace mesochain
