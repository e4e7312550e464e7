#include "input/hsd/hsd_values.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "input/text_reader.hpp"

namespace mesochain::input::hsd {

namespace {
std::string list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// "Key = value" content as one string (for messages).
std::string shown(const Node& node) {
  std::string out;
  for (const DataLine& d : node.data) out += (out.empty() ? "" : " ") + d.text;
  if (out.size() > 60) out = out.substr(0, 57) + "...";
  return out;
}

const DataLine& singleLine(const Node& node, const std::string& expected) {
  if (!node.children.empty())
    node.fail(fmt::format("a block ({} {{ ... }})", node.children.front().name), expected);
  if (node.data.size() != 1 || node.data.front().tokens.size() != 1)
    node.fail(node.data.empty() ? std::string("no value") : "'" + shown(node) + "'", expected);
  return node.data.front();
}
}  // namespace

void allowOnly(const Node& node, const std::vector<std::string>& allowed) {
  for (std::size_t i = 0; i < node.children.size(); ++i) {
    const Node& c = node.children[i];
    const bool known = std::any_of(allowed.begin(), allowed.end(), [&](const std::string& a) { return c.is(a); });
    if (!known)
      c.fail("the keyword '" + c.name + "', which mesochain does not read",
             (allowed.empty() ? std::string("no keywords here")
                              : "one of " + list(allowed)) +
                 " (the subset of DFTB+'s input that mesochain reads: docs/cell-file.md, "
                 "\"DFTB+ input\")");
    for (std::size_t k = 0; k < i; ++k)
      if (node.children[k].is(c.name))
        c.fail(fmt::format("'{}' a second time (first at line {})", c.name, node.children[k].line),
               "each keyword once");
  }
  if (!node.data.empty())
    throw InputError(node.data.front().file, fmt::format("line {}", node.data.front().line),
                     "the data '" + node.data.front().text + "' inside " +
                         (node.path.empty() ? std::string("the file") : node.path),
                     "keywords (Key = value) only");
}

void requireNoAttribute(const Node& node) {
  if (!node.attribute.empty())
    node.fail("the attribute [" + node.attribute + "]", "no attribute (unit) for " + node.name);
}

std::string word(const Node& node, const std::string& expected) {
  requireNoAttribute(node);
  return singleLine(node, expected).tokens.front();
}

namespace {
double realValue(const Node& node, const std::string& expected) {
  const std::string t = singleLine(node, expected).tokens.front();
  double x = 0;
  if (!objective::detail::parseReal(t, x)) node.fail("'" + t + "'", expected);
  return x;
}
}  // namespace

double real(const Node& node, const std::string& expected) {
  requireNoAttribute(node);
  return realValue(node, expected);
}

long integer(const Node& node, const std::string& expected) {
  requireNoAttribute(node);
  const std::string t = singleLine(node, expected).tokens.front();
  long n = 0;
  if (!objective::detail::parseInteger(t, n)) node.fail("'" + t + "'", expected);
  return n;
}

bool yesNo(const Node& node) {
  const std::string w = lowerCase(word(node, "Yes or No"));
  if (w != "yes" && w != "no") node.fail("'" + w + "'", "Yes or No");
  return w == "yes";
}

double withUnit(const Node& node, UnitKind kind, const std::string& defaultUnit, const std::string& expected) {
  const double x = realValue(node, expected);
  const std::string unit = node.attribute.empty() ? defaultUnit : node.attribute;
  const auto factor = unitFactor(kind, unit);
  if (!factor)
    node.fail("the unit [" + node.attribute + "]",
              std::string("one of DFTB+'s ") +
                  (kind == UnitKind::Length ? "length" : kind == UnitKind::Energy ? "energy" : "force") +
                  " units: " + unitNames(kind));
  return x * *factor;
}

const Node& method(const Node& node, const std::string& expected) {
  requireNoAttribute(node);
  if (node.children.size() != 1 || !node.data.empty() || !node.children.front().block)
    node.fail(node.data.empty() ? (node.children.empty() ? std::string("no method")
                                                         : fmt::format("{} entries", node.children.size()))
                                : "the value '" + shown(node) + "'",
              expected);
  return node.children.front();
}

std::vector<double> reals(const Node& node, std::size_t count, const std::string& expected) {
  requireNoAttribute(node);
  if (!node.children.empty()) node.fail("the keyword '" + node.children.front().name + "'", expected);
  std::vector<double> out;
  for (const DataLine& d : node.data)
    for (const std::string& t : d.tokens) {
      double x = 0;
      if (!objective::detail::parseReal(t, x))
        throw InputError(d.file, fmt::format("line {} ({})", d.line, node.path), "'" + t + "'", expected);
      out.push_back(x);
    }
  if (out.size() != count) node.fail(fmt::format("{} numbers", out.size()), expected);
  return out;
}

}  // namespace mesochain::input::hsd
