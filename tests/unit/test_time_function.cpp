#include "poroseam/time_function.hpp"

#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>

using poroseam::TimeFunction;

TEST(TimeFunction, StepSwitchesOnAfterZero)
{
  const auto f = TimeFunction::step();
  EXPECT_EQ(f.factor(0.0), 0.0);
  EXPECT_EQ(f.factor(1e-12), 1.0);
}

TEST(TimeFunction, RampThenHold)
{
  const auto f = TimeFunction::ramp(240.0);
  EXPECT_NEAR(f.factor(60.0), 0.25, 1e-15);
  EXPECT_EQ(f.factor(1e4), 1.0);
  EXPECT_EQ(f.factor(-1.0), 0.0);
}

TEST(TimeFunction, TableInterpolatesLinearly)
{
  const auto f = TimeFunction::table({0.0, 1.0, 3.0}, {0.0, 2.0, -2.0});
  EXPECT_NEAR(f.factor(0.5), 1.0, 1e-15);
  EXPECT_NEAR(f.factor(2.0), 0.0, 1e-15);
  EXPECT_NEAR(f.factor(10.0), -2.0, 1e-15);
}

TEST(TimeFunction, ReadsCsvAndRejectsBadTables)
{
  const std::string path = testing::TempDir() + "poroseam_table.csv";
  {
    std::ofstream out(path);
    out << "time,factor\n# comment\n0,0\n10,1e-3\n";
  }
  std::vector<double> t, v;
  EXPECT_EQ(poroseam::readTimeTable(path, t, v), "");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(v[1], 1e-3);
  {
    std::ofstream out(path);
    out << "0,0\n10,1\n5,2\n";
  }
  EXPECT_NE(poroseam::readTimeTable(path, t, v).find("line 3"), std::string::npos);
  EXPECT_NE(poroseam::readTimeTable(path + ".missing", t, v).find("cannot open"),
            std::string::npos);
  std::remove(path.c_str());
}
