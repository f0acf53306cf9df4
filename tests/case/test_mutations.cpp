// Robustness of the case reader (hardened input), a bounded and
// deterministic stand-in for fuzzing: thousands of random edits of a valid
// case (bytes replaced, deleted, duplicated; numbers made extreme) must each
// either read or fail with an InputError carrying a location — never another
// exception, a hang or a crash.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "case/case_reader.hpp"
#include "common/verification.hpp"

namespace camouflet {
namespace {

const char* valid = R"([run]
end_time = 0.001
cfl = 0.6
hourglass = { form = "viscous", coefficient = 0.1 }
[output]
gauge_interval = 1e-5
[materials.soil]
eos = { type = "linear", density = 2000.0, bulk_modulus = 6.6667e8 }
strength = { type = "elastic", shear_modulus = 4.0e8 }
[[parts]]
name = "column"
material = "soil"
initial_velocity = [0.0, 1.0]
block = { origin = [0.0, 0.0], size = [0.5, 2.0], cells = [2, 8], grading = [1.0, 2.0] }
[[boundary]]
type = "velocity"
set = "column.ymin"
components = ["y"]
value = [1.0]
history = [[0.0, 1.0], [1e-4, 0.0]]
[[gauges]]
name = "axis"
points = [{ name = "a", position = [0.25, 1.0] }]
[[gauges]]
name = "line"
from = [0.1, 0.1]
to = [0.4, 1.9]
count = 3
)";

TEST(CaseMutations, OnlyInputErrorsNeverCrashes) {
  ASSERT_NO_THROW(read_case_text(valid, "valid.toml"));
  std::mt19937_64 rng(20051);
  const std::string alphabet = "[]{}=,.\"'#\n -+0123456789eEinfa_xyzsoilcolumn";
  const std::vector<std::string> extremes = {"1e308",       "-1e308", "nan",  "inf", "0",  "-0.0", "1e-320",
                                             "99999999999", "-1",     "\"\"", "[]",  "{}", "true"};
  const int trials = 3000;
  int accepted = 0, refused = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int t = 0; t < trials; ++t) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < edits; ++k) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 5) {
        case 0:
          text[at] = alphabet[rng() % alphabet.size()];
          break;
        case 1:
          text.erase(at, 1 + rng() % 8);
          break;
        case 2:
          text.insert(at, text.substr(rng() % text.size(), 1 + rng() % 12));
          break;
        case 3: {
          // Replace the number starting at or after `at` by an extreme value.
          const std::size_t d = text.find_first_of("0123456789", at);
          if (d == std::string::npos) break;
          const std::size_t e = text.find_first_not_of("0123456789.e-", d);
          text.replace(d, (e == std::string::npos ? text.size() : e) - d, extremes[rng() % extremes.size()]);
          break;
        }
        default:
          text.insert(at, 1, alphabet[rng() % alphabet.size()]);
      }
    }
    try {
      read_case_text(text, "mutant.toml");
      ++accepted;
    } catch (const InputError& e) {
      ++refused;
      EXPECT_EQ(e.where().file, "mutant.toml") << e.what();
      EXPECT_FALSE(e.message().empty());
      if (e.where().line == 0 && e.where().key.empty())
        ADD_FAILURE() << "no location: " << e.what() << "\n" << text;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not an InputError: " << e.what() << "\n--- case ---\n" << text;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(accepted + refused, trials);
  EXPECT_GT(refused, trials / 3);  // most edits break something, and each was caught
  EXPECT_LT(seconds, 20.0);
}

}  // namespace
}  // namespace camouflet
