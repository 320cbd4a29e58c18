// The settings rows (core/settings.hpp): parsing, range checks and the generated help, independent of any table,
// and lifting rows into an outer struct.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/core/settings.hpp>

namespace hooke::settings {
namespace {

struct Inner {
  double length = 0.5;
  int passes = 2;
  bool on = false;
  std::string mode = "a";
};
struct Outer {
  Inner inner;
};

std::vector<Setting<Inner>> inner_rows() {
  std::vector<Setting<Inner>> r;
  Setting<Inner> length =
      number<Inner>("length", "m", 0.0, 2.0, kCalibrate, "A length", [](Inner& o) -> double& { return o.length; });
  length.exclusive_min = true;
  length.length_power = 1;
  r.push_back(length);
  r.push_back(integer<Inner>("passes", 0, 5, kCalibrate | kBatch, "Passes", [](Inner& o) -> int& { return o.passes; }));
  r.push_back(flag<Inner>("on", kBatch, "A switch", [](Inner& o) -> bool& { return o.on; }));
  r.push_back(choice<Inner>(
      "mode", kCalibrate, "A mode",
      [] {
        return std::vector<std::string>{"a", "b"};
      },
      [](Inner& o, std::string_view t) { o.mode = std::string(t); }, [](const Inner& o) { return o.mode; }));
  return r;
}

TEST(Settings, ParsesChecksAndNamesTheSetting) {
  const auto rows = inner_rows();
  const std::span<const Setting<Inner>> table(rows);
  Inner x;
  EXPECT_TRUE(set(table, x, "length", "1.5"));
  EXPECT_EQ(x.length, 1.5);
  EXPECT_TRUE(set(table, x, "length", "150", 0.01));  // cm on the command line: 1.5 m
  EXPECT_DOUBLE_EQ(x.length, 1.5);
  EXPECT_TRUE(set(table, x, "passes", "4"));
  EXPECT_EQ(x.passes, 4);
  EXPECT_TRUE(set(table, x, "on", "true"));
  EXPECT_TRUE(x.on);
  EXPECT_TRUE(set(table, x, "mode", "b"));
  EXPECT_EQ(x.mode, "b");
  EXPECT_FALSE(set(table, x, "nothing", "1"));
  auto message = [&](const char* name, const char* text) {
    try {
      set(table, x, name, text);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("length", "0"), "length must be in (0, 2] m, not 0");  // the exclusive minimum
  EXPECT_EQ(message("length", "2.5"), "length must be in (0, 2] m, not 2.5");
  EXPECT_EQ(message("length", "nan"), "length: 'nan' is not a finite number");
  EXPECT_EQ(message("passes", "6"), "passes must be in [0, 5], not 6");
  EXPECT_EQ(message("passes", "2.5"), "passes: '2.5' is not an integer");
  EXPECT_EQ(message("on", "maybe"), "on takes on or off, not 'maybe'");
  EXPECT_EQ(message("mode", "c"), "unknown mode 'c' (use a, b)");
  EXPECT_EQ(x.length, 1.5);  // nothing refused was set
  EXPECT_THROW(apply(table, x, {{"passes", "1"}, {"lenght", "1"}}, kCalibrate), InvalidArgument);
  EXPECT_EQ(x.passes, 1);
}

TEST(Settings, DescriptionsFilterByCommandAndGenerateTheirHelp) {
  const auto rows = inner_rows();
  const std::vector<Description> all = describe(std::span<const Setting<Inner>>(rows));
  const std::vector<Description> batch = describe(std::span<const Setting<Inner>>(rows), kBatch);
  ASSERT_EQ(all.size(), 4u);
  ASSERT_EQ(batch.size(), 2u);
  EXPECT_EQ(batch[0].name, "passes");
  EXPECT_EQ(all[0].default_text, "0.5");
  EXPECT_EQ(all[2].default_text, "off");
  EXPECT_EQ(all[0].long_help(), "A length (m; on the command line, the mesh file's unit); in (0, 2]");
  EXPECT_EQ(all[3].long_help(), "A mode; one of a, b");
  Description d;
  d.name = "fit-refinements";
  EXPECT_EQ(d.keyword(), "fit_refinements");
  EXPECT_EQ(canonical_name("fit_refinements"), "fit-refinements");
}

TEST(Settings, NumbersReadBackExactly) {
  for (double v : {0.1, 1.0 / 3.0, 14630.0, 1e-300, -2.5e17, 0.125})
    EXPECT_EQ(parse_number("v", number_text(v)), v) << number_text(v);
  EXPECT_EQ(number_text(0.1), "0.1");
  EXPECT_EQ(number_text(1000.0), "1000");
}

TEST(Settings, LiftedRowsReachTheInnerStruct) {
  const auto rows = inner_rows();
  const std::vector<Setting<Outer>> lifted =
      lift<Outer>(std::span<const Setting<Inner>>(rows), [](Outer& o) -> Inner& { return o.inner; });
  Outer o;
  EXPECT_TRUE(set(std::span<const Setting<Outer>>(lifted), o, "passes", "3"));
  EXPECT_EQ(o.inner.passes, 3);
  EXPECT_EQ(describe(lifted[0], o).default_text, "0.5");
  EXPECT_THROW(set(std::span<const Setting<Outer>>(lifted), o, "passes", "-1"), InvalidArgument);
}

}  // namespace
}  // namespace hooke::settings
