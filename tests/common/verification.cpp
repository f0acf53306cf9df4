#include "verification.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace camouflet::test {

namespace {

std::string json_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (c == '\n') {
      o += "\\n";
      continue;
    }
    o += c;
  }
  return o;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  return fmt::format("{:.9g}", v);
}

void append(const std::string& line) {
  const char* dir = std::getenv("CAMOUFLET_VERIFICATION_DIR");
  if (!dir || !*dir) return;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = info ? fmt::format("{}.{}", info->test_suite_name(), info->name()) : "unknown";
  std::filesystem::create_directories(dir);
  std::ofstream out(std::filesystem::path(dir) / (name + ".jsonl"), std::ios::app);
  out << line << '\n';
}

std::string test_name() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return info ? fmt::format("{}.{}", info->test_suite_name(), info->name()) : "unknown";
}

}  // namespace

double verify(const Verification& v) {
  const double diff = std::abs(v.computed - v.expected);
  const double error = v.relative ? diff / std::abs(v.expected) : diff;
  const bool passed = std::isfinite(error) && error <= v.tolerance;
  EXPECT_TRUE(passed) << v.problem << ": computed " << v.computed << " " << v.unit << ", expected " << v.expected
                      << " (" << v.reference << "), error " << error << " > tolerance " << v.tolerance;
  append(fmt::format(
      R"({{"test":"{}","problem":"{}","reference":"{}","expected":{},"computed":{},"unit":"{}","error":{},"relative":{},"tolerance":{},"passed":{}}})",
      json_escape(test_name()), json_escape(v.problem), json_escape(v.reference), number(v.expected),
      number(v.computed), json_escape(v.unit), number(error), v.relative ? "true" : "false", number(v.tolerance),
      passed ? "true" : "false"));
  return error;
}

void record_check(const std::string& problem, const std::string& reference, const std::string& outcome, bool passed) {
  EXPECT_TRUE(passed) << problem << ": " << outcome;
  append(fmt::format(R"({{"test":"{}","problem":"{}","reference":"{}","outcome":"{}","passed":{}}})",
                     json_escape(test_name()), json_escape(problem), json_escape(reference), json_escape(outcome),
                     passed ? "true" : "false"));
}

void record_observation(const std::string& problem, const std::string& reference, const std::string& outcome,
                        bool inside) {
  append(fmt::format(
      R"({{"test":"{}","problem":"{}","reference":"{}","outcome":"{}","passed":true,"asserted":false,"inside":{}}})",
      json_escape(test_name()), json_escape(problem), json_escape(reference), json_escape(outcome),
      inside ? "true" : "false"));
}

}  // namespace camouflet::test
