// A render step takes any `linkage render` option: every flag the command lists is a
// lesson key (besides the few that make no sense inside a lesson).
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

#include "lesson/schema.hpp"
#include "model/inputs.hpp"
#include "support/test_support.hpp"

namespace linkage::test {
namespace {

TEST(LessonRenderStep, TakesEveryRenderFlag) {
  const RunResult help = run_linkage({"render", "--help"});
  ASSERT_EQ(help.exit_code, 0);
  std::set<std::string> keys;
  for (const auto& k : lesson::step_keys("render")) keys.insert(std::string(k.name));
  for (const auto& k : lesson::run_keys()) keys.insert(std::string(k.name));
  for (const auto& k : lesson::common_step_keys()) keys.insert(std::string(k.name));  // mechanism
  for (const auto& k : kInputKeys) keys.insert(std::string(k.key));
  // Not lesson keys: the lesson names the output (out) in its folder, takes its inputs
  // from [parameters], [state] and set steps, and manages progress itself.
  const std::set<std::string> not_in_lessons{"help", "out", "frames", "quiet", "stats", "config"};

  const std::regex option(R"(^\s+(?:-h,)?--([A-Za-z0-9][A-Za-z0-9-]*))");
  int flags = 0;
  std::istringstream lines(help.out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, option)) continue;
    ++flags;
    std::string key = m[1].str();
    if (not_in_lessons.count(key)) continue;
    std::replace(key.begin(), key.end(), '-', '_');
    EXPECT_TRUE(keys.count(key)) << "linkage render --" << m[1].str() << " has no render step key '" << key << "'";
  }
  EXPECT_GT(flags, 30);
}

}  // namespace
}  // namespace linkage::test
