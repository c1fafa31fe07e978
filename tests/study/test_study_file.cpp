// Study files are checked before any point runs: the points a grid and a list make, their
// names and --set values, and a bad file stopping with the key named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "case/case_file.hpp"
#include "run/case_keys.hpp"
#include "study/reference_metrics.hpp"
#include "study/study_file.hpp"

namespace isphdem {
namespace {

namespace fs = std::filesystem;

class StudyFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(ISPHDEM_BINARY_DIR) / "test_output" / "study_file" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  Study load(const std::string& body, const std::vector<std::string>& extra = {}) {
    const fs::path f = dir_ / "study.toml";
    std::ofstream(f) << "base = \"" << ISPHDEM_SOURCE_DIR
                     << "/examples/taylor_green_2d/case.toml\"\n"
                     << body;
    return load_study(f, extra, case_keys());
  }
  std::string error(const std::string& body) {
    try {
      load(body);
    } catch (const CaseError& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

TEST_F(StudyFile, GridIsEveryCombinationAndPointsComeAfter) {
  const Study s = load(
      "[set]\n\"time.end\" = 0.5\n"
      "[grid]\n\"particles.spacing\" = [0.05, 0.025]\nsolver.preconditioner = [\"jacobi\", "
      "\"ilu0\", \"amg\"]\n"
      "[[points]]\nname = \"fine\"\nset = { \"particles.spacing\" = 0.0125 }\n");
  ASSERT_EQ(s.points.size(), 7u);
  EXPECT_EQ(s.varied, (std::vector<std::string>{"particles.spacing", "solver.preconditioner"}));
  EXPECT_EQ(s.points[0].name, "spacing=0.05_preconditioner=jacobi");
  EXPECT_EQ(s.points[5].name, "spacing=0.025_preconditioner=amg");
  EXPECT_EQ(s.points[0].overrides,
            (std::vector<std::string>{"time.end=0.5", "particles.spacing=0.05",
                                      "solver.preconditioner='jacobi'"}));
  EXPECT_EQ(s.points[6].name, "fine");
  EXPECT_EQ(s.points[6].values,
            (std::vector<std::pair<std::string, std::string>>{{"particles.spacing", "0.0125"}}));
}

TEST_F(StudyFile, SetOnTheCommandLineReachesEveryPointLast) {
  const Study s = load("[grid]\n\"particles.spacing\" = [0.05, 0.025]\n", {"time.end=0.1"});
  for (const auto& p : s.points) EXPECT_EQ(p.overrides.back(), "time.end=0.1");
}

TEST_F(StudyFile, SetOfAVariedKeyIsRefused) {
  try {
    load("[grid]\n\"particles.spacing\" = [0.05, 0.025]\n", {"particles.spacing=0.01"});
    FAIL() << "no error for --set of a varied key";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("is a key the study varies"), std::string::npos)
        << e.what();
  }
}

TEST_F(StudyFile, SameNameTwiceIsMadeUnique) {
  const Study s =
      load("[[points]]\nset = { \"time.end\" = 0.1 }\n[[points]]\nset = { \"time.end\" = 0.1 }\n");
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_NE(s.points[0].name, s.points[1].name);
}

TEST_F(StudyFile, BadFilesNameTheKey) {
  auto has = [](const std::string& message, const std::string& part) {
    return message.find(part) != std::string::npos;
  };
  std::string m = error("[grid]\n\"particles.spacng\" = [0.05]\n");
  EXPECT_TRUE(has(m, "'particles.spacng'") && has(m, "'particles.spacing'")) << m;
  m = error("[grid]\n\"particles.spacing\" = []\n");
  EXPECT_TRUE(has(m, "'particles.spacing' has no values")) << m;
  m = error("[grid]\n\"particles.spacing\" = 0.05\n");
  EXPECT_TRUE(has(m, "'particles.spacing' = 0.05 must be an array")) << m;
  m = error("[grid]\n\"particles.spacing\" = [\"fine\"]\n");
  EXPECT_TRUE(has(m, "'particles.spacing' = 'fine' is a string") && has(m, "a number")) << m;
  m = error("[set]\n\"solver.free_surface\" = 1\n[grid]\n\"time.end\" = [0.1]\n");
  EXPECT_TRUE(has(m, "'solver.free_surface'") && has(m, "true or false")) << m;
  m = error("");
  EXPECT_TRUE(has(m, "no points")) << m;
  m = error("[gird]\n\"time.end\" = [1.0]\n");
  EXPECT_TRUE(has(m, "unknown key 'gird'") && has(m, "'grid'")) << m;
  m = error("[[points]]\nname = \"a/b\"\nset = { \"time.end\" = 0.1 }\n");
  EXPECT_TRUE(has(m, "'a/b'")) << m;
  m = error("[[points]]\nname = \"study.csv\"\nset = { \"time.end\" = 0.1 }\n");
  EXPECT_TRUE(has(m, "'study.csv'")) << m;
  m = error("[grid]\n\"time.end\" = [0.1]\n[plot]\nmetric = \"amplitud\"\n");
  EXPECT_TRUE(has(m, "'amplitud'") && has(m, "amplitude")) << m;
  m = error("[grid]\n\"time.end\" = [0.1]\n[plot]\nseries = \"coupling.model\"\n");
  EXPECT_TRUE(has(m, "'coupling.model' is not a key the study varies")) << m;
  // The base case itself is checked too.
  const fs::path f = dir_ / "nobase.toml";
  std::ofstream(f) << "base = \"missing.toml\"\n[grid]\n\"time.end\" = [0.1]\n";
  try {
    load_study(f, {}, case_keys());
    ADD_FAILURE() << "no error for a missing base case";
  } catch (const CaseError& e) {
    EXPECT_TRUE(has(e.what(), "missing.toml")) << e.what();
  }
}

TEST_F(StudyFile, ReferenceMetricsAreCheckedWhenTheCaseLoads) {
  auto metric_error = [&](const std::string& metric) {
    const fs::path f = dir_ / "case.toml";
    std::ofstream(f) << "[case]\ndimension = 2\n[[reference.metrics]]\n" << metric;
    try {
      parse_reference(CaseFile::load(f, {}, case_keys()));
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(metric_error("name = \"a\"\nvalue = \"last(x\"\nexpected = 1.0\n")
                .find("reference.metrics[0].value"),
            std::string::npos);
  EXPECT_EQ(metric_error("name = \"a\"\nvalue = \"last(x)\"\n"), "(no error)");  // value alone
  EXPECT_NE(metric_error("value = \"last(x)\"\nexpected = 1.0\n").find("needs a name"),
            std::string::npos);
  EXPECT_NE(metric_error("name = \"a\"\nvalue = \"last(x)\"\nexpected = 1.0\nerror = \"rel\"\n")
                .find("\"relative\" or \"absolute\""),
            std::string::npos);
  // A column the run does not write stops it before the first step, with the closest name.
  const fs::path f = dir_ / "case.toml";
  std::ofstream(f) << "[case]\ndimension = 2\n[[reference.metrics]]\nname = \"a\"\n"
                   << "value = \"last(max_sped)\"\nexpected = 1.0\n";
  const auto metrics = parse_reference(CaseFile::load(f, {}, case_keys()));
  try {
    check_reference_columns(metrics, {"time", "max_speed"});
    ADD_FAILURE() << "no error for a missing column";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("closest is 'max_speed'"), std::string::npos) << e.what();
  }
  // Relative error, and absolute where the expected value is zero.
  DiagnosticsTable t;
  t.names = {"time", "max_sped"};
  t.columns = {{"time", {1.0}}, {"max_sped", {1.1}}};
  EXPECT_NEAR(evaluate_metric(metrics.at(0), t).error, 0.1, 1e-12);
  // Without an expected value the run reports the value alone; the error is for a study to give.
  std::ofstream(f) << "[case]\ndimension = 2\n[[reference.metrics]]\nname = \"a\"\n"
                   << "value = \"2 * last(max_sped)\"\n";
  const auto alone = evaluate_metric(parse_reference(CaseFile::load(f, {}, case_keys())).at(0), t);
  EXPECT_NEAR(alone.value, 2.2, 1e-12);
  EXPECT_TRUE(std::isnan(alone.expected) && std::isnan(alone.error));
}

// [reference.constants]: numbers, or a case key's number, so a formula follows a varied key.
TEST_F(StudyFile, ReferenceConstantsFollowTheCase) {
  const fs::path f = dir_ / "case.toml";
  auto load_case = [&](const std::string& constants, const std::vector<std::string>& set = {}) {
    std::ofstream(f) << "[case]\ndimension = 2\n[fluid]\nviscosity = 1e-6\n"
                     << "[reference.constants]\n"
                     << constants << "[[reference.metrics]]\nname = \"a\"\n"
                     << "value = \"last(x) * nu / k\"\nexpected = 1.0\n";
    return parse_reference(CaseFile::load(f, set, case_keys()));
  };
  DiagnosticsTable t;
  t.names = {"time", "x"};
  t.columns = {{"time", {1.0}}, {"x", {3.0}}};
  const auto m = load_case("nu = \"fluid.viscosity\"\nk = 2\n", {"fluid.viscosity=4e-6"});
  EXPECT_DOUBLE_EQ(evaluate_metric(m.at(0), t).value, 3.0 * 4e-6 / 2);
  auto message = [&](const std::string& constants) {
    try {
      load_case(constants);
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message("nu = \"fluid.viscosty\"\nk = 2\n").find("does not set 'fluid.viscosty'"),
            std::string::npos);
  EXPECT_NE(message("nu = true\nk = 2\n").find("reference.constants.nu must be a number"),
            std::string::npos);
  EXPECT_NE(message("nu = 1\npi = 3\nk = 2\n").find("not pi"), std::string::npos);
  // A formula's unknown name says where constants come from.
  EXPECT_NE(message("nu = 1\n").find("[reference.constants]"), std::string::npos);
}

TEST_F(StudyFile, ReferencePointMustBeAPointOfTheStudy) {
  const std::string grid = "[grid]\n\"particles.spacing\" = [0.05, 0.025]\n";
  EXPECT_EQ(load("reference = \"spacing=0.025\"\n" + grid).reference_point, "spacing=0.025");
  const std::string m = error("reference = \"spacing=0.0025\"\n" + grid);
  EXPECT_NE(m.find("\"spacing=0.0025\" is not a point of the study"), std::string::npos) << m;
  EXPECT_NE(m.find("'spacing=0.025'"), std::string::npos) << m;
  EXPECT_NE(error("reference = 3\n" + grid).find("the name of a point"), std::string::npos);
}

// Every study of examples/studies loads as `isphdem study` loads it (keys, points, [plot]), so a
// renamed case key or a plot option a study names but the code lost stops here, not after an
// hour of points. The convergence study must keep its chart's key among the varied ones.
TEST_F(StudyFile, EveryExampleStudyLoads) {
  int n = 0;
  for (const auto& e :
       fs::directory_iterator(fs::path(ISPHDEM_SOURCE_DIR) / "examples" / "studies")) {
    if (e.path().extension() != ".toml") continue;
    SCOPED_TRACE(e.path().string());
    Study s;
    EXPECT_NO_THROW(s = load_study(e.path(), {}, case_keys()));
    EXPECT_FALSE(s.points.empty());
    if (e.path().stem() == "erosion_dt") {
      EXPECT_EQ(s.convergence, "time.dt");
      EXPECT_EQ(s.points.size(), 28u);
    }
    ++n;
  }
  EXPECT_GE(n, 13);
}

}  // namespace
}  // namespace isphdem
