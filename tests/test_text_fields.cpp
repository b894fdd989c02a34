// The whitespace splitting shared by the structure readers and the text mesh formats.
#include <gtest/gtest.h>

#include <string_view>
#include <vector>

#include "io/text_fields.hpp"

namespace molsurf {
namespace {

using Fields = std::vector<std::string_view>;

TEST(TextFields, SplitsOnEveryKindOfBlankAndKeepsTheRest) {
  EXPECT_EQ(text::split_fields("ATOM 1\tCA \r"), (Fields{"ATOM", "1", "CA"}));
  EXPECT_EQ(text::split_fields("  1.5\v-2e3\f+0.25  "), (Fields{"1.5", "-2e3", "+0.25"}));
  // Anything that is not one of the five blanks belongs to a field (commas, NUL, non-ASCII).
  EXPECT_EQ(text::split_fields(std::string_view("a,b c\0d é", 10)), (Fields{"a,b", std::string_view("c\0d", 3), "é"}));
}

TEST(TextFields, ABlankOrEmptyLineHasNoFields) {
  EXPECT_TRUE(text::split_fields("").empty());
  EXPECT_TRUE(text::split_fields(" \t\r\v\f ").empty());
}

TEST(TextFields, FieldsAreViewsIntoTheLine) {
  const std::string_view line = "x  yz";
  const Fields fields = text::split_fields(line);
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[1].data(), line.data() + 3);
}

}  // namespace
}  // namespace molsurf
