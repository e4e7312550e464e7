#pragma once
// CSV as RFC 4180 writes it: fields separated by commas, records by "\n"; a field that holds a
// comma, a double quote, a line break or leading/trailing spaces is enclosed in double quotes,
// with each double quote inside doubled ("(10,10)" -> "\"(10,10)\""). Every CSV mesochain writes
// goes through csvField/csvRecord; csvParseRecord reads one record back (the round trip is
// tested in tests/common/test_csv.cpp).
#include <string>
#include <string_view>
#include <vector>

namespace mesochain {

// The field as it must appear in a record.
std::string csvField(std::string_view text);
// The fields joined by commas, each through csvField, ending in "\n".
std::string csvRecord(const std::vector<std::string>& fields);
// The fields of one record (without its line break; a quoted field may hold commas, doubled
// quotes and line breaks). Returns false when a quoted field is not closed or a quote is
// followed by anything but a comma or the end.
bool csvParseRecord(std::string_view record, std::vector<std::string>& fields);

}  // namespace mesochain
