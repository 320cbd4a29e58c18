#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/core/units.hpp>

namespace hooke {
namespace {

TEST(ParseError, NamesFileAndLine) {
  const ParseError e("mesh.msh", 12, "bad node");
  EXPECT_STREQ(e.what(), "mesh.msh:12: bad node");
  EXPECT_EQ(e.line(), 12);
  const ParseError b = ParseError::at_byte("mesh.stl", 84, "file ends");
  EXPECT_STREQ(b.what(), "mesh.stl: at byte 84: file ends");
  EXPECT_EQ(b.byte_offset(), 84);
}

TEST(Units, ConvertsKnownUnitsAndRejectsOthers) {
  EXPECT_DOUBLE_EQ(metres_per_unit("cm"), 0.01);
  EXPECT_DOUBLE_EQ(metres_per_unit("mm"), 0.001);
  EXPECT_THROW(metres_per_unit("inch"), InvalidArgument);
}

}  // namespace
}  // namespace hooke
