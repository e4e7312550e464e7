#include "input/hsd/hsd_tree.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::input::hsd {

namespace fs = std::filesystem;

std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool Node::is(const std::string& n) const { return lowerCase(name) == lowerCase(n); }

const Node* Node::child(const std::string& n) const {
  for (const Node& c : children)
    if (c.is(n)) return &c;
  return nullptr;
}

std::string Node::where() const {
  return path.empty() ? fmt::format("line {}", line) : fmt::format("line {} ({})", line, path);
}

void Node::fail(const std::string& found, const std::string& expected) const {
  throw InputError(file, where(), found, expected);
}

namespace {

constexpr int kMaxIncludeDepth = 16;

enum class Kind { Word, String, Open, Close, Equals, Attribute, End, Newline, IncludeText, IncludeHsd, Eof };

struct Token {
  Kind kind;
  std::string text;
  int line;
};

bool isSpecial(char c) {
  return c == '{' || c == '}' || c == '=' || c == ';' || c == '#' || c == '"' || c == '\'' ||
         c == '[' || c == ']';
}

std::vector<Token> tokenize(const std::string& text, const std::string& source) {
  std::vector<Token> out;
  int line = 1;
  std::size_t i = 0;
  auto fail = [&](const std::string& found, const std::string& expected) {
    throw InputError(source, fmt::format("line {}", line), found, expected);
  };
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      out.push_back({Kind::Newline, "", line++});
      ++i;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == '{' || c == '}' || c == '=' || c == ';') {
      out.push_back({c == '{' ? Kind::Open : c == '}' ? Kind::Close : c == '=' ? Kind::Equals : Kind::End,
                     std::string(1, c), line});
      ++i;
    } else if (c == '[') {
      const std::size_t close = text.find_first_of("]\n", i);
      if (close == std::string::npos || text[close] != ']')
        fail("an attribute '[' without its ']' on the same line", "[unit], e.g. Temperature [Kelvin] = 300");
      std::string a = text.substr(i + 1, close - i - 1);
      a.erase(0, a.find_first_not_of(" \t"));
      a.erase(a.find_last_not_of(" \t") + 1);
      out.push_back({Kind::Attribute, a, line});
      i = close + 1;
    } else if (c == ']') {
      fail("a ']' without its '['", "[unit] after a tag name");
    } else if (c == '"' || c == '\'') {
      const std::size_t close = text.find_first_of(std::string(1, c) + "\n", i + 1);
      if (close == std::string::npos || text[close] != c)
        fail(fmt::format("a string opened with {} and not closed on the same line", c),
             "a closing quote on the same line");
      out.push_back({Kind::String, text.substr(i + 1, close - i - 1), line});
      i = close + 1;
    } else if (text.compare(i, 3, "<<<") == 0 || text.compare(i, 3, "<<!") == 0) {
      const Kind kind = text[i + 2] == '<' ? Kind::IncludeText : Kind::IncludeHsd;
      const std::string op = text.substr(i, 3);
      i += 3;
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
      if (i >= text.size() || (text[i] != '"' && text[i] != '\''))
        fail(op + " without a quoted file name", op + " \"file\"");
      const char q = text[i];
      const std::size_t close = text.find_first_of(std::string(1, q) + "\n", i + 1);
      if (close == std::string::npos || text[close] != q)
        fail(op + " with an unclosed file name", op + " \"file\"");
      out.push_back({kind, text.substr(i + 1, close - i - 1), line});
      i = close + 1;
    } else {
      const std::size_t start = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) && !isSpecial(text[i])) ++i;
      out.push_back({Kind::Word, text.substr(start, i - start), line});
    }
  }
  out.push_back({Kind::Eof, "", line});
  return out;
}

std::string readWholeFile(const std::string& path, const std::string& source, const std::string& where,
                          const std::string& what) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError(source, where, "\"" + path + "\", which does not exist", what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(source, where, "\"" + path + "\", which cannot be read", what);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class Parser {
 public:
  Parser(std::string source, std::vector<Token> tokens, int depth)
      : source_(std::move(source)), tokens_(std::move(tokens)), depth_(depth) {}

  // Fills `parent` with the content up to its closing brace (inBlock) or to the end.
  void content(Node& parent, bool inBlock, int openLine) {
    for (;;) {
      const Token& t = tokens_[pos_];
      switch (t.kind) {
        case Kind::Newline:
        case Kind::End:
          ++pos_;
          continue;
        case Kind::Close:
          if (!inBlock) fail(t.line, "a '}' that closes no block", "a tag, data or the end of the file");
          ++pos_;
          return;
        case Kind::Eof:
          if (inBlock)
            fail(t.line, fmt::format("the end of the file inside the block opened at line {}", openLine),
                 "a '}' closing it");
          return;
        case Kind::IncludeText:
          ++pos_;
          includeText(parent, t);
          break;
        case Kind::IncludeHsd:
          ++pos_;
          includeHsd(parent, t);
          break;
        case Kind::Word:
        case Kind::String:
          if (isTag()) tag(parent);
          else dataLine(parent);
          break;
        default:
          fail(t.line, "'" + t.text + "'", "a tag name, data or '}'");
      }
      if (!parent.children.empty() && !parent.data.empty())
        fail(t.line,
             fmt::format("both child tags and data inside {}", parent.path.empty() ? "the file" : parent.path),
             "either tags (Key = value, Key { ... }) or data lines, not both");
    }
  }

 private:
  [[noreturn]] void fail(int line, const std::string& found, const std::string& expected) const {
    throw InputError(source_, fmt::format("line {}", line), found, expected);
  }

  // A word followed by an optional [attribute] and then '=' or '{'.
  bool isTag() const {
    if (tokens_[pos_].kind != Kind::Word) return false;
    std::size_t k = pos_ + 1;
    if (tokens_[k].kind == Kind::Attribute) ++k;
    return tokens_[k].kind == Kind::Equals || tokens_[k].kind == Kind::Open;
  }

  Node makeNode(const Node& parent, const Token& name) const {
    Node n;
    n.name = name.text;
    n.file = source_;
    n.line = name.line;
    n.path = parent.path.empty() ? name.text : parent.path + "/" + name.text;
    return n;
  }

  void tag(Node& parent) {
    Node n = makeNode(parent, tokens_[pos_++]);
    if (tokens_[pos_].kind == Kind::Attribute) n.attribute = tokens_[pos_++].text;
    if (tokens_[pos_].kind == Kind::Open) {
      ++pos_;
      n.block = true;
      content(n, true, n.line);
    } else {
      ++pos_;  // '='
      const Token& v = tokens_[pos_];
      if (v.kind == Kind::Open) {
        ++pos_;
        n.block = true;
        content(n, true, v.line);
      } else if (v.kind == Kind::Word && (tokens_[pos_ + 1].kind == Kind::Open ||
                                          (tokens_[pos_ + 1].kind == Kind::Attribute &&
                                           tokens_[pos_ + 2].kind == Kind::Open))) {
        Node method = makeNode(n, tokens_[pos_++]);
        if (tokens_[pos_].kind == Kind::Attribute) method.attribute = tokens_[pos_++].text;
        ++pos_;  // '{'
        method.block = true;
        content(method, true, method.line);
        n.children.push_back(std::move(method));
      } else {
        DataLine d{source_, v.line, "", {}};
        while (tokens_[pos_].kind == Kind::Word || tokens_[pos_].kind == Kind::String) add(d, tokens_[pos_++]);
        const Kind k = tokens_[pos_].kind;
        if (k != Kind::Newline && k != Kind::End && k != Kind::Close && k != Kind::Eof)
          fail(tokens_[pos_].line, "'" + tokens_[pos_].text + "' in the value of " + n.name,
               "Key = value (to the end of the line), Key = Method { ... } or Key { ... }");
        if (!d.tokens.empty()) n.data.push_back(std::move(d));
      }
    }
    parent.children.push_back(std::move(n));
  }

  static void add(DataLine& d, const Token& t) {
    d.text += (d.text.empty() ? "" : " ") + (t.kind == Kind::String ? "\"" + t.text + "\"" : t.text);
    d.tokens.push_back(t.text);
  }

  void dataLine(Node& parent) {
    DataLine d{source_, tokens_[pos_].line, "", {}};
    while (tokens_[pos_].kind == Kind::Word || tokens_[pos_].kind == Kind::String) add(d, tokens_[pos_++]);
    const Token& t = tokens_[pos_];
    if (t.kind == Kind::Equals || t.kind == Kind::Open || t.kind == Kind::Attribute)
      fail(t.line, "'" + t.text + "' after the data '" + d.text + "'",
           "a tag name (one word) before '=' or '{', or data without '=' and '{'");
    parent.data.push_back(std::move(d));
  }

  std::string resolve(const std::string& file) const {
    const fs::path p(file);
    return (p.is_absolute() ? p : fs::path(source_).parent_path() / p).lexically_normal().string();
  }

  void includeText(Node& parent, const Token& t) {
    const std::string path = resolve(t.text);
    const std::string text = readWholeFile(path, source_, fmt::format("line {}", t.line),
                                           "an existing file for <<< (relative to " + source_ + ")");
    std::istringstream in(text);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      DataLine d{path, number, line, {}};
      std::istringstream fields(line);
      for (std::string f; fields >> f;) d.tokens.push_back(f);
      if (!d.tokens.empty()) parent.data.push_back(std::move(d));
    }
  }

  void includeHsd(Node& parent, const Token& t) {
    if (depth_ >= kMaxIncludeDepth)
      fail(t.line, fmt::format("<<! nested more than {} deep", kMaxIncludeDepth),
           "includes that do not include themselves");
    const std::string path = resolve(t.text);
    const std::string text = readWholeFile(path, source_, fmt::format("line {}", t.line),
                                           "an existing HSD file for <<! (relative to " + source_ + ")");
    Parser inner(path, tokenize(text, path), depth_ + 1);
    Node holder;
    holder.path = parent.path;
    inner.content(holder, false, 0);
    for (Node& c : holder.children) parent.children.push_back(std::move(c));
    for (DataLine& d : holder.data) parent.data.push_back(std::move(d));
  }

  std::string source_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  int depth_;
};

}  // namespace

Node parseHsdText(const std::string& text, const std::string& source) {
  Parser p(source, tokenize(text, source), 0);
  Node root;
  root.file = source;
  p.content(root, false, 0);
  return root;
}

Node parseHsdFile(const std::string& path) {
  return parseHsdText(readWholeFile(path, path, "the file", "an existing DFTB+ input file (dftb_in.hsd)"),
                      path);
}

}  // namespace mesochain::input::hsd
