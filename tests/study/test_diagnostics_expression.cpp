// The formulas of [reference] metrics over diagnostics.csv columns: arithmetic as written,
// reductions over the right rows, and errors that name what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

#include "study/diagnostics_expression.hpp"
#include "study/diagnostics_table.hpp"

namespace isphdem {
namespace {

DiagnosticsTable table() {
  DiagnosticsTable t;
  t.names = {"time", "speed", "energy"};
  t.columns["time"] = {0.1, 0.2, 0.3, 0.4};
  t.columns["speed"] = {1.0, 3.0, 2.0, 6.0};
  t.columns["energy"] = {16.0, 8.0, 4.0, 2.0};
  return t;
}

double eval(const std::string& text) { return DiagnosticsExpression(text).evaluate(table()); }

TEST(DiagnosticsExpression, ArithmeticFollowsPrecedence) {
  EXPECT_DOUBLE_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("2 ^ 3 ^ 2"), 512.0);  // right-associative
  EXPECT_DOUBLE_EQ(eval("-2 ^ 2"), -4.0);      // as in mathematics
  EXPECT_DOUBLE_EQ(eval("8 / 4 / 2"), 1.0);    // left-associative
  EXPECT_DOUBLE_EQ(eval("1.5e2 - 50"), 100.0);
  EXPECT_DOUBLE_EQ(eval("sqrt(16) + abs(-1) + max(2, 5) + min(2, 5)"), 12.0);
  EXPECT_NEAR(eval("exp(log(3)) + log10(1000)"), 6.0, 1e-12);
  EXPECT_NEAR(eval("pi"), M_PI, 0.0);
}

TEST(DiagnosticsExpression, ReductionsReadTheRightRows) {
  EXPECT_DOUBLE_EQ(eval("first(speed)"), 1.0);
  EXPECT_DOUBLE_EQ(eval("last(speed)"), 6.0);
  EXPECT_DOUBLE_EQ(eval("max(speed)"), 6.0);
  EXPECT_DOUBLE_EQ(eval("min(speed)"), 1.0);
  EXPECT_DOUBLE_EQ(eval("mean(speed)"), 3.0);
  EXPECT_DOUBLE_EQ(eval("at(speed, 0.25)"), 2.5);  // halfway between 3 and 2
  EXPECT_DOUBLE_EQ(eval("at(speed, 0.0)"), 1.0);   // before the first row: the first
  EXPECT_DOUBLE_EQ(eval("mean_after(speed, 0.3)"), 4.0);
  EXPECT_DOUBLE_EQ(eval("max_after(speed, 0.15)"), 6.0);
  EXPECT_DOUBLE_EQ(eval("min_after(energy, 0.15)"), 2.0);
  EXPECT_DOUBLE_EQ(eval("sqrt(last(energy) / first(energy))"), std::sqrt(2.0 / 16.0));
  EXPECT_DOUBLE_EQ(eval("max(last(speed), first(energy))"), 16.0);  // the two-number max
}

// The analytic references against values computed by hand and the textbook table.
TEST(ReferenceFormulas, TerminalVelocitiesAndErgun) {
  // 0.1 mm quartz in water: Re = 0.87, Stokes (1600 * 9.81 * 1e-8 / 18e-3 m/s).
  EXPECT_NEAR(eval("stokes_velocity(1e-4, 2600, 1000, 1e-6, 9.81)"), 8.72e-3, 1e-5);
  // At Re << 1 Schiller-Naumann tends to Stokes; 1 mm sand: 0.152 m/s (Re ~ 150).
  EXPECT_NEAR(eval("schiller_naumann_velocity(1e-5, 2600, 1000, 1e-6, 9.81) / "
                   "stokes_velocity(1e-5, 2600, 1000, 1e-6, 9.81)"),
              1.0, 0.01);
  EXPECT_NEAR(eval("schiller_naumann_velocity(1e-3, 2600, 1000, 1e-6, 9.81)"), 0.152, 0.002);
  // The drag at that velocity balances the buoyant weight.
  const double v = eval("schiller_naumann_velocity(1e-3, 2600, 1000, 1e-6, 9.81)");
  const double re = 1e-3 * v / 1e-6;
  const double cd = 24 / re * (1 + 0.15 * std::pow(re, 0.687));
  EXPECT_NEAR(cd * M_PI * 1e-6 / 8 * 1000 * v * v, 1600 * 9.81 * M_PI * 1e-9 / 6, 1e-12);
  // Ergun at eps = 0.4, d = 1 mm, U = 1 mm/s in water: 150*1e-3*0.36*1e-3/(0.064*1e-6) +
  // 1.75*1000*0.6*1e-6/(0.064*1e-3) = 843.75 + 16.40625 Pa/m.
  EXPECT_NEAR(eval("ergun_gradient(0.4, 1e-3, 1e-6, 1000, 1e-3)"), 860.15625, 1e-9);
  EXPECT_THROW(eval("schiller_naumann_velocity(1e-3, 900, 1000, 1e-6, 9.81)"), std::runtime_error);
  // Simple cubic arrays against Zick & Homsy (1982, Table 2): K = 2.008 at phi = 0.027, 2.810
  // at 0.064, 4.292 at 0.125; a lone sphere (phi -> 0) has K = 1.
  EXPECT_NEAR(eval("cubic_array_drag_factor(0.027)"), 2.008, 0.002);
  EXPECT_NEAR(eval("cubic_array_drag_factor(0.064)"), 2.810, 0.003);
  EXPECT_NEAR(eval("cubic_array_drag_factor(0.125)"), 4.292, 0.005);
  EXPECT_THROW(eval("cubic_array_drag_factor(0.2)"), std::runtime_error);
}

TEST(DiagnosticsExpression, ListsTheColumnsItReads) {
  const DiagnosticsExpression e("last(speed) / at(energy, 0.2)");
  EXPECT_EQ(e.columns(), (std::vector<std::string>{"energy", "speed", "time"}));
}

TEST(DiagnosticsExpression, SyntaxErrorsSayWhatWasExpectedWhere) {
  auto message = [](const std::string& text) {
    try {
      DiagnosticsExpression e(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message("foo(speed)").find("not 'foo'"), std::string::npos) << message("foo(speed)");
  EXPECT_NE(message("speed + 1").find("last(speed)"), std::string::npos);
  EXPECT_NE(message("last(speed").find("')'"), std::string::npos);
  EXPECT_NE(message("1 +").find("the end"), std::string::npos);
  EXPECT_NE(message("at(speed)").find("',' and a time"), std::string::npos);
  EXPECT_NE(message("sqrt(1, 2)").find("takes 1 argument"), std::string::npos);
  EXPECT_NE(message("2 3").find("column 3"), std::string::npos);
}

TEST(DiagnosticsExpression, NamedConstantsAreNumbers) {
  const std::map<std::string, double> c{{"d", 0.002}, {"cells", 4.0}};
  EXPECT_DOUBLE_EQ(DiagnosticsExpression("last(speed) / (cells * d)^2", c).evaluate(table()),
                   6.0 / 64e-6);
  // A constant is a number, not a column: min(d, 1) is the function of two numbers.
  EXPECT_DOUBLE_EQ(DiagnosticsExpression("min(d, 1)", c).evaluate(table()), 0.002);
  EXPECT_TRUE(DiagnosticsExpression("2 * d", c).columns().empty());
  // A name given to a reduction is its column, also where a constant has that name.
  EXPECT_DOUBLE_EQ(
      DiagnosticsExpression("max(speed) + mean_after(speed, d)", {{"speed", 9.0}, {"d", 0.3}})
          .evaluate(table()),
      6.0 + 4.0);
  // Without the constant the name is a column read without a reduction.
  EXPECT_THROW(DiagnosticsExpression("2 * d"), std::invalid_argument);
}

TEST(DiagnosticsExpression, EvaluationErrorsNameTheColumn) {
  try {
    eval("last(sped)");
    FAIL() << "no error for a missing column";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no column 'sped'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("speed"), std::string::npos) << e.what();
  }
  EXPECT_THROW(eval("mean_after(speed, 1.0)"), std::runtime_error);  // no row after t = 1
}

TEST(DiagnosticsTable, ReadsWhatTheWriterWroteAndDropsACutLine) {
  const auto path = std::filesystem::temp_directory_path() / "isphdem_diag_table.csv";
  std::ofstream(path) << "time,step,max_speed\n0.1,1,2.5\n0.2,2,nan\n0.3,3,1e-3\n0.4,4";
  const auto t = read_diagnostics(path);
  ASSERT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.names, (std::vector<std::string>{"time", "step", "max_speed"}));
  EXPECT_DOUBLE_EQ(t.columns.at("max_speed")[2], 1e-3);
  EXPECT_TRUE(std::isnan(t.columns.at("max_speed")[1]));
  std::filesystem::remove(path);
  EXPECT_THROW(read_diagnostics(path), std::runtime_error);
}

}  // namespace
}  // namespace isphdem
