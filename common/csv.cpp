#include "common/csv.hpp"

namespace mesochain {

std::string csvField(std::string_view text) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string_view::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote) return std::string(text);
  std::string q = "\"";
  for (char c : text) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

std::string csvRecord(const std::vector<std::string>& fields) {
  std::string r;
  for (std::size_t i = 0; i < fields.size(); ++i) r += (i ? "," : "") + csvField(fields[i]);
  return r + "\n";
}

bool csvParseRecord(std::string_view record, std::vector<std::string>& fields) {
  fields.clear();
  std::size_t i = 0;
  while (true) {
    std::string field;
    if (i < record.size() && record[i] == '"') {
      ++i;
      while (true) {
        if (i >= record.size()) return false;  // unclosed quote
        if (record[i] == '"') {
          if (i + 1 < record.size() && record[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        field += record[i++];
      }
      if (i < record.size() && record[i] != ',') return false;
    } else {
      while (i < record.size() && record[i] != ',') {
        if (record[i] == '"') return false;  // a quote inside an unquoted field
        field += record[i++];
      }
    }
    fields.push_back(std::move(field));
    if (i >= record.size()) return true;
    ++i;  // the comma
  }
}

}  // namespace mesochain
