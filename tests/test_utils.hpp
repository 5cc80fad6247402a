// Shared test helpers: the scalar types under test and comparisons carried out
// in the type itself (EXPECT_NEAR would narrow long double, float128 and MPFR to double).
#pragma once

#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/core/widen.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include <unistd.h>

namespace viscor::test {

/// Fixed-precision scalar types every numerical test runs over.
using all_real_types = ::testing::Types<double, long double
#if VISCOR_HAS_FLOAT128
                                        , quad
#endif
#if VISCOR_HAS_MPFR
                                        , mpfr_50, mpfr_100
#endif
                                        >;

/// Relative difference |a - b| / |b| (absolute when b = 0), in Real.
template <class Real>
Real relative_difference(const Real& a, const Real& b) {
  using std::abs;
  return b == 0 ? Real(abs(a)) : Real(abs(a - b) / abs(b));
}

/// Decimal digits on which a and b agree: -log10 of their relative difference.
template <class Real>
double agreeing_digits(const Real& a, const Real& b) {
  using std::log10;
  const Real d = relative_difference(a, b);
  if (d == 0) return decimal_digits<Real>() + 1.0;
  return static_cast<double>(-log10(d));
}

/// EXPECT_PRED_FORMAT3(relative_close, actual, expected, tolerance): |a - e| <= tol |e|.
template <class Real>
::testing::AssertionResult relative_close(const char* a_expr, const char* e_expr, const char*, const Real& a,
                                          const Real& e, const Real& tol) {
  const Real d = relative_difference(a, e);
  if (d <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a_expr << " = " << to_decimal_string(a) << "\n  vs " << e_expr << " = "
                                       << to_decimal_string(e) << "\n  relative difference " << to_decimal_string(d, 4)
                                       << " > tolerance " << to_decimal_string(tol, 4);
}

/// EXPECT_PRED_FORMAT3(relatively_close, actual, expected, tolerance) where actual
/// and tolerance may be of other types: both are converted to the type of `expected`.
template <class Real, class A, class T>
::testing::AssertionResult relatively_close(const char* a_expr, const char* e_expr, const char* t_expr,
                                            const A& actual, const Real& expected, const T& tolerance) {
  return relative_close<Real>(a_expr, e_expr, t_expr, Real(actual), expected, Real(tolerance));
}

/// A reference constant given as a decimal string, correctly rounded to Real.
template <class Real>
Real constant(const std::string& digits) {
  return parse_real<Real>(digits, "reference constant");
}

/// k machine epsilons of Real.
template <class Real>
Real ulps(int k) {
  return Real(k) * epsilon<Real>();
}

/// EXPECT_PRED_FORMAT3(absolute_close, actual, expected, tolerance): |a - e| <= tol.
template <class Real>
::testing::AssertionResult absolute_close(const char* a_expr, const char* e_expr, const char*, const Real& a,
                                          const Real& e, const Real& tol) {
  using std::abs;
  const Real d = abs(a - e);
  if (d <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a_expr << " = " << to_decimal_string(a) << "\n  vs " << e_expr << " = "
                                       << to_decimal_string(e) << "\n  absolute difference " << to_decimal_string(d, 4)
                                       << " > tolerance " << to_decimal_string(tol, 4);
}

/// Converts x into To: exactly by the library's widening rule (detail::widen) where To
/// holds every value of From, else rounded through a round-trip decimal string.
template <class To, class From>
To convert(const From& x) {
  if constexpr (std::is_same_v<To, From> || (detail::can_widen<To, From>() && has_fixed_precision<From>()))
    return detail::widen<To>(x);
  else
    return parse_real<To>(to_decimal_string(x, roundtrip_digits<From>() + 2), "converted value");
}

/// Result of running the viscor CLI: exit status and both streams.
struct cli_run {
  int status = -1;
  std::string out, err;
};

/// Runs `viscor ARGS` (VISCOR_CLI_PATH, set by CMake) and captures its output.
/// Runs the viscor binary (by default the released one; VISCOR_CLI_TEST_HOOKS_PATH
/// for the test binary whose test seams are enabled, src/cli/test_hooks.hpp).
inline cli_run run_cli(const std::string& args, const std::string& program = VISCOR_CLI_PATH) {
  // NOTE: ctest -j runs test processes side by side: name the capture files per process.
  static int calls = 0;
  const std::string stem = ::testing::TempDir() + "viscor_cli_" + std::to_string(::getpid()) + "_" + std::to_string(++calls);
  const std::string out = stem + ".out", err = stem + ".err";
  const std::string command = program + " " + args + " > " + out + " 2> " + err;
  cli_run r;
  const int raw = std::system(command.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  auto slurp = [](const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  r.out = slurp(out), r.err = slurp(err);
  std::remove(out.c_str());
  std::remove(err.c_str());
  return r;
}

/// A fresh empty directory TempDir()/<prefix>XXXXXX for the lifetime of the object,
/// removed with everything in it at the end; `path` is empty if it could not be made.
struct scratch_dir {
  std::filesystem::path path;
  explicit scratch_dir(const std::string& prefix) {
    std::string name = ::testing::TempDir() + prefix + "XXXXXX";
    if (::mkdtemp(name.data())) path = name;
  }
  ~scratch_dir() {
    std::error_code ec;
    if (!path.empty()) std::filesystem::remove_all(path, ec);
  }
  scratch_dir(const scratch_dir&) = delete;
  scratch_dir& operator=(const scratch_dir&) = delete;
};

/// A test with its own empty scratch directory, TempDir()/<prefix><test name>:
/// removed after a passing test, kept for inspection after a failing one. The
/// table runner's test hooks set by a test are unset after it.
class scratch_dir_test : public ::testing::Test {
 protected:
  explicit scratch_dir_test(std::string prefix) : m_prefix(std::move(prefix)) {}
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = std::filesystem::path(::testing::TempDir()) / (m_prefix + info->name());
    std::filesystem::remove_all(m_dir);
    std::filesystem::create_directories(m_dir);
  }
  void TearDown() override {
    unsetenv("VISCOR_TABLE_STOP_AFTER");
    unsetenv("VISCOR_TABLE_SHIFT_CERTIFIED_E");
    if (!HasFailure()) std::filesystem::remove_all(m_dir);
  }
  std::string path(const std::string& name) const { return (m_dir / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  static std::string read(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  /// The names of the files in the scratch directory, sorted.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(m_dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  std::string m_prefix;
  std::filesystem::path m_dir;
};

}  // namespace viscor::test

#define VISCOR_EXPECT_REL(actual, expected, tolerance) \
  EXPECT_PRED_FORMAT3(::viscor::test::relatively_close, actual, expected, tolerance)
