// The HSD reader (input/hsd/hsd_tree.hpp): the tree of a DFTB+-style input, line numbers,
// includes, and the errors for input that is not HSD.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "hsd_support.hpp"

#include "common/errors.hpp"
#include "input/hsd/hsd_tree.hpp"

using namespace mesochain;
using namespace mesochain::input::hsd;

using mesochain::testing::errorOf;

namespace {
std::string tempDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("mesochain-hsd-tree-" + name);
  std::filesystem::create_directories(d);
  return d.string();
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST(HsdTree, NestedBlocksValuesAttributesAndLines) {
  const Node root = parseHsdText(R"(# a comment line
Hamiltonian = DFTB {
  SCC = Yes   # trailing comment
  Filling = Fermi {
    Temperature [Kelvin] = 300
  }
  MaxAngularMomentum { C = "p"; H = 's' }
  KPointsAndWeights = HelicalUniform { 40 0.5 }
}
Driver = {}
)",
                                 "in.hsd");
  ASSERT_EQ(root.children.size(), 2u);
  const Node& h = root.children[0];
  EXPECT_EQ(h.name, "Hamiltonian");
  EXPECT_EQ(h.line, 2);
  ASSERT_EQ(h.children.size(), 1u);
  const Node& dftb = h.children[0];
  EXPECT_TRUE(dftb.is("dftb"));  // names match without regard to case
  EXPECT_TRUE(dftb.block);
  const Node* scc = dftb.child("scc");
  ASSERT_NE(scc, nullptr);
  EXPECT_EQ(scc->line, 3);
  ASSERT_EQ(scc->data.size(), 1u);
  EXPECT_EQ(scc->data[0].tokens, std::vector<std::string>{"Yes"});
  EXPECT_EQ(scc->path, "Hamiltonian/DFTB/SCC");
  const Node& t = dftb.child("Filling")->children.at(0).children.at(0);
  EXPECT_EQ(t.name, "Temperature");
  EXPECT_EQ(t.attribute, "Kelvin");
  EXPECT_EQ(t.line, 5);
  EXPECT_EQ(t.data.at(0).tokens.at(0), "300");
  const Node* l = dftb.child("MaxAngularMomentum");
  ASSERT_EQ(l->children.size(), 2u);  // ';' ends a statement like a line break
  EXPECT_EQ(l->children[0].data[0].tokens[0], "p");
  EXPECT_EQ(l->children[1].data[0].tokens[0], "s");
  const Node& k = dftb.child("KPointsAndWeights")->children.at(0);
  EXPECT_EQ(k.name, "HelicalUniform");
  EXPECT_EQ(k.data.at(0).tokens, (std::vector<std::string>{"40", "0.5"}));
  const Node& driver = root.children[1];
  EXPECT_TRUE(driver.block);
  EXPECT_TRUE(driver.children.empty());
  EXPECT_TRUE(driver.data.empty());
  EXPECT_EQ(driver.where(), "line 10 (Driver)");
}

TEST(HsdTree, IncludesKeepTheirFilesAndLines) {
  const std::string d = tempDir("include");
  write(d + "/geo.gen", "2 C\nC\n\n1 1 0 0 0\n2 1 0 0 1.4\n");
  write(d + "/part.hsd", "\nAnalysis {\n  PrintForces = Yes\n}\n");
  write(d + "/dftb_in.hsd", "Geometry = GenFormat {\n  <<< \"geo.gen\"\n}\n<<! \"part.hsd\"\n");
  const Node root = parseHsdFile(d + "/dftb_in.hsd");
  const Node& gen = root.child("Geometry")->children.at(0);
  ASSERT_EQ(gen.data.size(), 4u);  // blank lines are dropped, the others keep their numbers
  EXPECT_EQ(gen.data[0].text, "2 C");
  EXPECT_EQ(gen.data[2].line, 4);
  EXPECT_EQ(gen.data[2].file, d + "/geo.gen");
  const Node* a = root.child("Analysis");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->file, d + "/part.hsd");
  EXPECT_EQ(a->line, 2);
  EXPECT_EQ(a->child("PrintForces")->line, 3);
}

TEST(HsdTree, ErrorsNameTheFileAndLine) {
  // A block that is never closed: the line of the end of the file and where it opened.
  std::string m = errorOf([] { parseHsdText("Hamiltonian = DFTB {\n  SCC = Yes\n", "a.hsd"); });
  EXPECT_NE(m.find("a.hsd, line 3"), std::string::npos) << m;
  EXPECT_NE(m.find("opened at line 1"), std::string::npos) << m;
  m = errorOf([] { parseHsdText("Options {\n}\n}\n", "b.hsd"); });
  EXPECT_NE(m.find("b.hsd, line 3"), std::string::npos) << m;
  m = errorOf([] { parseHsdText("A {\n  B = 1\n  1 2 3\n}\n", "c.hsd"); });
  EXPECT_NE(m.find("both child tags and data"), std::string::npos) << m;
  m = errorOf([] { parseHsdText("Prefix = \"/a/b\n", "d.hsd"); });
  EXPECT_NE(m.find("d.hsd, line 1"), std::string::npos) << m;
  m = errorOf([] { parseHsdText("T [K = 3\n", "e.hsd"); });
  EXPECT_NE(m.find("attribute"), std::string::npos) << m;
  const std::string d = tempDir("missing");
  write(d + "/in.hsd", "\nGeometry = GenFormat {\n  <<< \"nothere.gen\"\n}\n");
  m = errorOf([&] { parseHsdFile(d + "/in.hsd"); });
  EXPECT_NE(m.find("line 3"), std::string::npos) << m;
  EXPECT_NE(m.find("nothere.gen"), std::string::npos) << m;
  m = errorOf([&] { parseHsdFile(d + "/absent.hsd"); });
  EXPECT_NE(m.find("absent.hsd"), std::string::npos) << m;
  // An include of itself stops at a depth limit instead of recursing forever.
  write(d + "/self.hsd", "<<! \"self.hsd\"\n");
  m = errorOf([&] { parseHsdFile(d + "/self.hsd"); });
  EXPECT_NE(m.find("nested"), std::string::npos) << m;
}
