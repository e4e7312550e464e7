// RFC 4180 fields: what needs quotes gets them, and every field survives a write-read round trip.
#include <gtest/gtest.h>

#include "common/csv.hpp"

namespace mesochain {

TEST(Csv, QuotesOnlyWhatRfc4180Requires) {
  EXPECT_EQ(csvField("10"), "10");
  EXPECT_EQ(csvField("stretch"), "stretch");
  EXPECT_EQ(csvField("(10,10)"), "\"(10,10)\"");
  EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csvField("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csvField(" padded"), "\" padded\"");
  EXPECT_EQ(csvField(""), "");
  EXPECT_EQ(csvRecord({"(10,10)", "300", "8"}), "\"(10,10)\",300,8\n");
}

TEST(Csv, RoundTripKeepsEveryField) {
  const std::vector<std::string> fields = {"(10,10)", "", "a\"b", ",", "\"", "x y", " lead", "tail ",
                                           "1e-5", "cr\rlf\n"};
  std::string record = csvRecord(fields);
  record.pop_back();  // the record's line break
  std::vector<std::string> back;
  ASSERT_TRUE(csvParseRecord(record, back));
  EXPECT_EQ(back, fields);
  // The header count equals the field count although a field holds a comma (issue 18: 7 fields
  // under 6 headers before).
  ASSERT_TRUE(csvParseRecord("\"(10,10)\",300,8,0.1,-1.2,3e-9", back));
  EXPECT_EQ(back.size(), 6u);
  EXPECT_EQ(back[0], "(10,10)");
}

TEST(Csv, MalformedRecordsAreRefused) {
  std::vector<std::string> f;
  EXPECT_FALSE(csvParseRecord("\"open,1", f));
  EXPECT_FALSE(csvParseRecord("\"a\"b,1", f));
  EXPECT_FALSE(csvParseRecord("a\"b,1", f));
  EXPECT_TRUE(csvParseRecord("", f));
  EXPECT_EQ(f, std::vector<std::string>{""});
}

}  // namespace mesochain
