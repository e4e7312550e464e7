#pragma once
// A reader of HSD, the "human-readable structured data" of DFTB+ input files (dftb_in.hsd;
// the format as described in the DFTB+ manual and by the hsd-python documentation):
//
//   Tag = value tokens            a tag with data (to the end of the line or a ';')
//   Tag [unit] = 300              a tag with an attribute (DFTB+: the unit)
//   Tag { ... }   Tag = { ... }   a tag whose content is a block
//   Tag = Method { ... }          a tag with one child node, the method, and its block
//   # comment                     to the end of the line
//   "quoted" or 'quoted'          one token (may hold blanks)
//   <<< "file"                    the lines of the file as data (e.g. a .gen geometry)
//   <<! "file"                    the nodes of another HSD file
//
// A block holds either child nodes or data lines, never both. Tag names are matched without
// regard to case. Every node and data line keeps its file and line for errors, which are
// InputError(file, "line N (Path/To/Tag)", found, expected).
#include <string>
#include <vector>

namespace mesochain::input::hsd {

struct DataLine {
  std::string file;
  int line = 0;
  std::string text;                 // the line (comments removed for HSD text)
  std::vector<std::string> tokens;  // blank-separated; quotes removed
};

struct Node {
  std::string name;       // as written
  std::string attribute;  // the text inside [ ], trimmed; empty when there is none
  std::string file;
  int line = 0;
  std::string path;       // "Hamiltonian/DFTB/SCC" (names as written)
  bool block = false;     // its content was written in braces
  std::vector<Node> children;
  std::vector<DataLine> data;

  // Case-insensitive name test and lookup of the first child of a name.
  bool is(const std::string& name) const;
  const Node* child(const std::string& name) const;
  // "line 7 (Hamiltonian/DFTB/SCC)".
  std::string where() const;
  [[noreturn]] void fail(const std::string& found, const std::string& expected) const;
};

// The root node (name "", path "") holds the top-level nodes. A missing file, an unreadable
// include, an unbalanced brace or a block with both nodes and data is an InputError.
Node parseHsdFile(const std::string& path);
Node parseHsdText(const std::string& text, const std::string& source);

// Lower-case ASCII copy.
std::string lowerCase(std::string s);

}  // namespace mesochain::input::hsd
