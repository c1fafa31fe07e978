// The [dem] case table and the fluid/DEM time-step check.
#include "dem/dem_case_config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;
using isphdem::parse_dem_table;

class DemTable : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(ISPHDEM_BINARY_DIR) / "tests" / "dem_case_config";
    fs::create_directories(dir_);
    std::ofstream(dir_ / "in.test") << "# empty\n";
  }
  toml::table table(const std::string& text) { return toml::parse(text); }
  std::string error_of(const std::string& text) {
    try {
      parse_dem_table(table(text), dir_);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(DemTable, ParsesAllKeys) {
  auto c = parse_dem_table(table(R"(
    script = "in.test"
    substeps = 100
    log = "log.dem"
    screen = "/dev/null"
    [variables]
    nGrains = 500
    dmin = 0.001
    name = "fine"
    flag = true
  )"),
                           dir_);
  EXPECT_EQ(c.script, dir_ / "in.test");
  EXPECT_EQ(c.substeps, 100);
  ASSERT_EQ(c.variables.size(), 5u);
  // Sorted by name; case_dir added for the script's own files.
  const std::string dir = fs::absolute(dir_).lexically_normal().string();
  EXPECT_EQ(c.variables[0], (std::pair<std::string, std::string>{"case_dir", dir}));
  EXPECT_EQ(c.variables[1], (std::pair<std::string, std::string>{"dmin", "0.001"}));
  EXPECT_EQ(c.variables[2].second, "1");
  EXPECT_EQ(c.variables[3].second, "500");
  EXPECT_EQ(c.variables[4].second, "fine");
  auto args = c.liggghts_args("/out");
  std::vector<std::string> want = {"-var",    "case_dir",     dir,       "-var",     "dmin",
                                   "0.001",   "-var",         "flag",    "1",        "-var",
                                   "nGrains", "500",          "-var",    "name",     "fine",
                                   "-log",    "/out/log.dem", "-screen", "/dev/null"};
  EXPECT_EQ(args, want);
  EXPECT_EQ(isphdem::dem_table_keys().size(), 5u);
}

TEST_F(DemTable, CaseDirVariableCanBeOverridden) {
  auto c = parse_dem_table(
      table("script = \"in.test\"\nsubsteps = 1\n[variables]\ncase_dir = \"/x\"\n"), dir_);
  ASSERT_EQ(c.variables.size(), 1u);
  EXPECT_EQ(c.variables[0], (std::pair<std::string, std::string>{"case_dir", "/x"}));
}

TEST_F(DemTable, UnknownKeySuggestsClosest) {
  const auto e = error_of("script = \"in.test\"\nsubstep = 10\n");
  EXPECT_NE(e.find("substep"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'substeps'"), std::string::npos) << e;
}

TEST_F(DemTable, BadValuesNameTheKey) {
  EXPECT_NE(error_of("substeps = 10\n").find("[dem] script: missing"), std::string::npos);
  EXPECT_NE(error_of("script = \"nope.in\"\nsubsteps = 1\n").find("no such file"),
            std::string::npos);
  EXPECT_NE(error_of("script = \"in.test\"\n").find("[dem] substeps: missing"), std::string::npos);
  EXPECT_NE(error_of("script = \"in.test\"\nsubsteps = 0\n").find("integer >= 1"),
            std::string::npos);
  EXPECT_NE(error_of("script = \"in.test\"\nsubsteps = 2.5\n").find("integer >= 1"),
            std::string::npos);
  EXPECT_NE(error_of("script = \"in.test\"\nsubsteps = 1\nscreen = \"none\"\n").find("crash"),
            std::string::npos);
  EXPECT_NE(error_of("script = \"in.test\"\nsubsteps = 1\nvariables = 3\n").find("[dem] variables"),
            std::string::npos);
  EXPECT_NE(error_of("script = \"in.test\"\nsubsteps = 1\n[variables]\n\"a b\" = 1\n")
                .find("variables.a b"),
            std::string::npos);
}

TEST(FluidDtCheck, AcceptsExactMultipleRejectsOthers) {
  EXPECT_NO_THROW(isphdem::check_fluid_dt(1e-4, 100, 1e-6));
  EXPECT_NO_THROW(isphdem::check_fluid_dt(1e-4 * (1 + 5e-10), 100, 1e-6));
  try {
    isphdem::check_fluid_dt(1e-4 * (1 + 2e-9), 100, 1e-6);
    FAIL() << "expected a mismatch";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("substeps"), std::string::npos) << e.what();
  }
  EXPECT_THROW(isphdem::check_fluid_dt(1e-4, 99, 1e-6), std::runtime_error);
}

}  // namespace
