// The one strict TOML table reader (common/toml_table.hpp): every error names the file, the
// dotted key and its line, what was found and what was expected; optional keys, arrays, vectors,
// arrays of tables and quantities in several units.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/toml_table.hpp"
#include "tests/support/expect_input_error.hpp"

namespace mesochain {
namespace {

toml::value parse(const std::string& text) {
  std::istringstream in(text);
  return toml::parse(in, "t.toml");
}

using mesochain::testing::expectInputError;

TEST(TomlTable, OptionalKeysTakeTheFallbackOnlyWhenAbsent) {
  const toml::value v = parse("a = 2\ns = \"x\"\nv = [1, 2.5, 3]\n");
  const TomlTable t("t.toml", v, "");
  EXPECT_EQ(t.numberOr("a", 7.0), 2.0);
  EXPECT_EQ(t.numberOr("b", 7.0), 7.0);
  EXPECT_EQ(t.integerOr("a", 5), 2);
  EXPECT_EQ(t.stringOr("s", "y"), "x");
  EXPECT_EQ(t.stringOr("z", "y"), "y");
  EXPECT_EQ(t.vec3("v"), Eigen::Vector3d(1.0, 2.5, 3.0));
  EXPECT_EQ(t.vec3Or("w", Eigen::Vector3d::UnitZ()), Eigen::Vector3d::UnitZ());
  EXPECT_TRUE(t.isString("s"));
  EXPECT_FALSE(t.isString("a"));
  expectInputError([&] { t.stringOr("a", "y"); }, {"t.toml", "key a (line 1)", "an integer (2)", "a string"});
}

TEST(TomlTable, ArraysAndVectorsAreChecked) {
  const toml::value v = parse("two = [1.0, 2.0]\nmixed = [1, \"b\"]\nnames = [\"a\", 3]\n");
  const TomlTable t("t.toml", v, "");
  expectInputError([&] { t.vec3("two"); }, {"key two (line 1)", "2 numbers", "3 numbers [x, y, z]"});
  expectInputError([&] { t.numbers("mixed"); }, {"key mixed (line 2)", "a string", "finite numbers"});
  expectInputError([&] { t.integers("mixed"); }, {"key mixed", "an array of integers"});
  expectInputError([&] { t.strings("names"); }, {"key names (line 3)", "an integer (3)", "strings"});
  expectInputError([&] { t.numbers("none"); }, {"key none", "required"});
}

TEST(TomlTable, ArraysOfTablesAreNamedByIndex) {
  const toml::value v = parse("[[item]]\nn = 1\n[[item]]\nn = 2\nm = 3\n[box]\nx = 1\n");
  const TomlTable t("t.toml", v, "");
  const auto items = t.tables("item");
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[1].integer("n"), 2);
  expectInputError([&] { items[1].allowOnly({"n"}); }, {"key item[1].m (line 5)", "unknown key 'm'", "n"});
  expectInputError([&] { t.tables("box"); }, {"key box", "a table", "an array of tables [[box]]"});
  EXPECT_EQ(t.requireTable("box").integer("x"), 1);
  expectInputError([&] { t.requireTable("nothing"); }, {"key nothing", "required", "a table [nothing]"});
}

TEST(TomlTable, RangesAndSigns) {
  const toml::value v = parse("n = 0\nx = -1.5\ny = 2\n");
  const TomlTable t("t.toml", v, "");
  expectInputError([&] { t.integerIn("n", 1, 10); }, {"key n (line 1)", "an integer (0)", "an integer from 1 to 10"});
  EXPECT_EQ(t.integerIn("y", 1, 10), 2);
  expectInputError([&] { t.positive("x"); }, {"key x (line 2)", "-1.5", "a positive number"});
  expectInputError([&] { t.nonNegativeOr("x", 0.0); }, {"key x", "a number >= 0"});
  EXPECT_EQ(t.nonNegativeOr("absent", -1.0), -1.0);  // the fallback is the caller's
}

TEST(TomlTable, OneQuantityInOneUnit) {
  const toml::value v = parse("a_eV = 2.0\nb_eV = 1.0\nb_hartree = 3.0\nc_eV = -1\n");
  const TomlTable t("t.toml", v, "");
  EXPECT_DOUBLE_EQ(*t.quantity({{"a_hartree", 1.0}, {"a_eV", 0.5}}), 1.0);
  EXPECT_FALSE(t.quantity({{"d_hartree", 1.0}, {"d_eV", 0.5}}).has_value());
  expectInputError([&] { t.quantity({{"b_eV", 0.5}, {"b_hartree", 1.0}}); },
              {"key b_hartree (line 3)", "also b_eV", "one key per quantity"});
  expectInputError([&] { t.positiveQuantity({{"c_eV", 0.5}}); }, {"key c_eV (line 4)", "a value > 0"});
}

TEST(TomlTable, NumbersOrStringsAreReadAsText) {
  const toml::value v = parse("k = [12, 0.5, 1e-5, \"ewald\", 300.0, -2]\nb = [1, true]\n"
                              "inf = [1, inf]\nnone = 3\nempty = []\n");
  const TomlTable t("t.toml", v, "");
  EXPECT_EQ(t.numbersOrStrings("k"), (std::vector<std::string>{"12", "0.5", "1e-05", "ewald", "300", "-2"}));
  EXPECT_TRUE(t.numbersOrStrings("empty").empty());
  expectInputError([&] { t.numbersOrStrings("b"); },
                   {"t.toml", "key b (line 2)", "an array holding a boolean (true)", "an array of numbers or strings"});
  expectInputError([&] { t.numbersOrStrings("inf"); }, {"key inf (line 3)", "a float (inf)"});
  expectInputError([&] { t.numbersOrStrings("none", "settings"); }, {"key none (line 4)", "an integer (3)", "settings"});
  expectInputError([&] { t.numbersOrStrings("absent"); }, {"key absent", "required"});
}

TEST(TomlTable, RowsOfAnArrayOfArraysAreReadByIndex) {
  const toml::value v = parse("atoms = [[\"C\", 0.0, 1, 2.5],\n  [\"H\", 1.0, 0.0, 0.5]]\n"
                              "short = [[\"C\", 0.0, 1, 2.5],\n  [\"H\", 1.0]]\n"
                              "typed = [[\"C\", \"x\", 1, 2.5]]\nempty = []\nflat = [1, 2]\n");
  const TomlTable t("t.toml", v, "");
  const auto rows = t.rows("atoms", 4, "atoms [\"El\", x, y, z]", "atom");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].string(0), "H");
  EXPECT_EQ(rows[0].number(2), 1.0);  // an integer is a number
  EXPECT_EQ(rows[0].number(3), 2.5);
  expectInputError([&] { rows[1].integer(1); }, {"key atoms, atom 2 (line 2)", "entry 2: a float (1)"});
  expectInputError([&] { t.rows("short", 4, "atoms", "atom"); },
                   {"key short, atom 2 (line 4)", "an array of 2 entries, not 4", "expected atoms"});
  expectInputError([&] { t.rows("typed", 4, "atoms", "atom")[0].number(1); }, {"key typed, atom 1", "entry 2: a string (\"x\")"});
  expectInputError([&] { t.rows("empty", 2, "pairs"); }, {"key empty", "an array that is empty"});
  expectInputError([&] { t.rows("flat", 2, "pairs"); }, {"key flat, entry 1", "an integer (1)"});
  expectInputError([&] { t.rows("absent", 2, "pairs"); }, {"key absent", "required"});
}

TEST(TomlTable, IntegerOrOneWord) {
  const toml::value v = parse("all = \"all\"\nn = 12\nzero = 0\nword = \"some\"\nx = 1.5\n");
  const TomlTable t("t.toml", v, "");
  EXPECT_FALSE(t.integerOrWord("all", "all", 1, 100).has_value());
  EXPECT_EQ(t.integerOrWord("n", "all", 1, 100), 12);
  expectInputError([&] { t.integerOrWord("zero", "all", 1, 100, "samples"); },
                   {"key zero (line 3)", "an integer (0)", "\"all\" or an integer from 1 to 100 (samples)"});
  expectInputError([&] { t.integerOrWord("word", "all", 1, 100); }, {"key word", "a string (\"some\")"});
  expectInputError([&] { t.integerOrWord("x", "all", 1, 100); }, {"key x", "a float (1.5)"});
}

TEST(TomlTable, OneOfAListOfWords) {
  const toml::value v = parse("[shape]\nsection = \"square\"\nok = \"circle\"\nn = 2\n");
  const TomlTable t = TomlTable("t.toml", v, "").requireTable("shape");
  const std::vector<std::string> sections{"rectangle", "circle", "annulus"};
  EXPECT_EQ(t.oneOf("ok", sections), "circle");
  EXPECT_EQ(t.oneOfOr("absent", sections, "rectangle"), "rectangle");
  expectInputError([&] { t.oneOf("section", sections); },
                   {"key shape.section (line 2)", "a string (\"square\")", "\"rectangle\", \"circle\" or \"annulus\""});
  expectInputError([&] { t.oneOfOr("n", sections, "circle"); }, {"key shape.n (line 4)", "an integer (2)", "\"annulus\""});
  expectInputError([&] { t.oneOf("absent", sections); }, {"key shape.absent (table [shape] at line 1)", "required"});
}

TEST(TomlTable, PositiveOrAndOwnExpectations) {
  const toml::value v = parse("zero = 0\nx = 2\nv = [1, \"a\"]\nflat = 1\n");
  const TomlTable t("t.toml", v, "");
  EXPECT_EQ(t.positiveOr("x", 7.0), 2.0);
  EXPECT_EQ(t.positiveOr("absent", 7.0), 7.0);
  expectInputError([&] { t.positiveOr("zero", 1.0, "a tolerance > 0"); }, {"key zero (line 1)", "an integer (0)", "a tolerance > 0"});
  expectInputError([&] { t.numbers("v", "strains"); }, {"key v (line 3)", "an array holding a string (\"a\")", "strains"});
  expectInputError([&] { t.strings("v", "pairs \"A-B\""); }, {"key v", "an integer (1)", "pairs \"A-B\""});
  expectInputError([&] { t.integers("v", "orders"); }, {"key v", "a string", "orders"});
  expectInputError([&] { t.table("flat", "a table of shells"); }, {"key flat (line 4)", "an integer (1)", "a table of shells"});
  expectInputError([&] { t.requireTable("absent", "a confinement table"); }, {"key absent", "required", "a confinement table"});
}

TEST(TomlTable, AllowedTablesAreNamedInBrackets) {
  const toml::value v = parse("a = 1\n[box]\nx = 1\n[boks]\ny = 2\n");
  const TomlTable t("t.toml", v, "");
  expectInputError([&] { t.allowOnly({"a", "[box]"}); },
                   {"key boks (line 4)", "an unknown key 'boks'", "top-level keys or tables: a, [box]"});
  const toml::value w = parse("a = 1\n[box]\nx = 1\n");
  TomlTable("t.toml", w, "").allowOnly({"a", "[box]"});  // no error
}

}  // namespace
}  // namespace mesochain
