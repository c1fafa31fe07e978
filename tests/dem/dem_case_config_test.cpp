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
  EXPECT_EQ(c.exchange, isphdem::DemExchange::sequential);  // the default
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
  EXPECT_EQ(isphdem::dem_table_keys().size(), 7u);
  EXPECT_EQ(
      parse_dem_table(table("script = \"in.test\"\nsubsteps = 1\nexchange = \"staggered\"\n"), dir_)
          .exchange,
      isphdem::DemExchange::staggered);
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
  const auto exchange = error_of("script = \"in.test\"\nsubsteps = 1\nexchange = \"parallel\"\n");
  EXPECT_NE(exchange.find("[dem] exchange: 'parallel' is not an exchange"), std::string::npos)
      << exchange;
  EXPECT_NE(exchange.find("\"staggered\""), std::string::npos) << exchange;
  EXPECT_NE(error_of("script = \"in.test\"\nsubsteps = 1\nvariables = 3\n").find("[dem] variables"),
            std::string::npos);
  EXPECT_NE(error_of("script = \"in.test\"\nsubsteps = 1\n[variables]\n\"a b\" = 1\n")
                .find("variables.a b"),
            std::string::npos);
}

// A read_restart of a file that does not exist stops before LIGGGHTS starts (LIGGGHTS would end
// the process with MPI_ABORT), naming the file, the line and the case's [dem] prepare command.
// The path is expanded as LIGGGHTS does: -var values (the [dem.variables]) over index defaults,
// ${name} and $x, `&` continuations, comments.
TEST_F(DemTable, MissingRestartNamesFileLineAndPrepareCommand) {
  std::ofstream(dir_ / "in.restart") << "variable packing index packing.restart  # default\n"
                                        "variable packing_dir index ${case_dir}\n"
                                        "atom_modify map array\n"
                                        "read_restart &\n"
                                        "    ${packing_dir}/$p_${packing} # p is set by the case\n";
  const std::string dir = fs::absolute(dir_).lexically_normal().string();
  const auto e = error_of(
      "script = \"in.restart\"\nsubsteps = 1\n"
      "prepare = \"isphdem dem in.packing -var packing red.restart\"\n"
      "[variables]\npacking = \"red.restart\"\np = \"x\"\n");
  EXPECT_NE(e.find("[dem] the script in.restart (line 4: read_restart) reads '" + dir +
                   "/x_red.restart', which does not exist"),
            std::string::npos)
      << e;
  // The command with this isphdem's path, from the case's directory.
  EXPECT_NE(e.find("Make it first ([dem] prepare in the case file):\n  cd " + dir + " && /"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("/dem_case_config_test dem in.packing -var packing red.restart"),
            std::string::npos)
      << e;
  // Without prepare, the key is named.
  EXPECT_NE(error_of("script = \"in.restart\"\nsubsteps = 1\n[variables]\np = \"x\"\n")
                .find("x_packing.restart', which does not exist (make it first; [dem] prepare"),
            std::string::npos);
  // Once the file exists the table parses.
  std::ofstream(dir_ / "x_red.restart") << "";
  EXPECT_EQ(error_of("script = \"in.restart\"\nsubsteps = 1\n[variables]\n"
                     "packing = \"red.restart\"\np = \"x\"\n"),
            "");
  fs::remove(dir_ / "x_red.restart");
  // A path with a variable the scan cannot know ($(...), an equal-style variable) is left to
  // LIGGGHTS.
  std::ofstream(dir_ / "in.unknown") << "variable n equal 2\nread_restart ${n}/a.restart\n"
                                        "read_restart $(1+1).restart\n";
  EXPECT_EQ(error_of("script = \"in.unknown\"\nsubsteps = 1\n"), "");
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
