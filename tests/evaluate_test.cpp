// viscor::evaluate: the empirical bound is never violated (random points against
// references at higher precision by other methods: the adaptive solver, certify; a
// reduced sample of the 500-point sweep to 1e-40 of evaluate_slow_test here),
// approximations only inside a map, the cheapest qualifying method, exact forms,
// relative bounds on 1 - e, and input validation.
#include "evaluate_test_utils.hpp"

#include <viscor/exact/exact_solutions.hpp>

namespace viscor {
namespace {

using test::check_counts;
using test::scene_point;

const std::map<std::string, std::shared_ptr<error_map>>& maps() {
  static const auto m = test::test_maps(1);  // corners only: fast to build
  return m;
}

TEST(evaluate, never_violates_its_bound_double_range) {
  check_counts counts;
  for (const scene_point& p : test::random_points(7, 60, 2, 13))
    EXPECT_TRUE(test::check_point(p, maps().at(p.law.name).get(), test::adaptive_reference, counts));
  // The sample exercises the approximations as well as the solver.
  int approximations = 0;
  for (const auto& [method, n] : counts.by_method)
    if (method != "taylor" && method != "exact" && method != "certified") approximations += n;
  EXPECT_GT(approximations, 5);
  EXPECT_GT(counts.by_method["taylor"], 5);
}

TEST(evaluate, never_violates_its_bound_beyond_double) {
  check_counts counts;
  for (const scene_point& p : test::random_points(11, 8, 16, 32))
    EXPECT_TRUE(test::check_point(p, maps().at(p.law.name).get(), test::adaptive_reference, counts));
  EXPECT_GT(counts.by_method["certified"], 0);
}

TEST(evaluate, never_violates_its_bound_on_a_reduced_sample_to_1e_40) {
  // The first 20 points of evaluate_slow_test's 500, against certified values.
  const auto slow_maps = test::test_maps(2);
  check_counts counts;
  for (const scene_point& p : test::random_points(20240607, 20, 2, 40))
    EXPECT_TRUE(test::check_point(p, slow_maps.at(p.law.name).get(), test::certified_reference, counts));
  EXPECT_EQ(counts.checked, 20);
  EXPECT_GE(test::references_used().certified, 15);
}

TEST(evaluate, approximations_only_inside_the_map) {
  const contact_law law = law_by_name("kuwabara_kono");
  evaluate_options with_map;
  with_map.map = maps().at(law.name).get();
  // Inside the map at a loose tolerance: an approximation, the cheapest whose bound qualifies.
  const evaluation<double> in = evaluate(law, 0.005, 0.2, 1e-2, with_map);
  EXPECT_LT(static_cast<int>(in.method), static_cast<int>(evaluation_method::exact));
  const auto b = with_map.map->at(0.005, 0.2);
  ASSERT_TRUE(b.has_value());
  for (int k = 0; k < static_cast<int>(in.method); ++k) EXPECT_TRUE(!b->bound[k] || *b->bound[k] > 1e-2);
  EXPECT_EQ(in.bound, *b->bound[static_cast<std::size_t>(in.method)]);
  EXPECT_FALSE(in.contact_time.has_value());
  // Outside (gamma > 0.3, g > 10, g < 0), without a map, or asking for T_f: never.
  for (auto [gamma, g] : {std::pair{0.5, 0.2}, {0.005, 20.0}, {0.005, -0.1}}) {
    const evaluation<double> out = evaluate(law, gamma, g, 0.5, with_map);
    EXPECT_EQ(out.method, evaluation_method::taylor) << gamma << ", " << g;
  }
  EXPECT_EQ(evaluate(law, 0.005, 0.2, 1e-2).method, evaluation_method::taylor);
  evaluate_options timed = with_map;
  timed.need_contact_time = true;
  const evaluation<double> t = evaluate(law, 0.005, 0.2, 1e-2, timed);
  EXPECT_EQ(t.method, evaluation_method::taylor);
  ASSERT_TRUE(t.contact_time.has_value());
  EXPECT_GT(*t.contact_time, 0);
  // A map for another law is refused.
  EXPECT_THROW(evaluator<double>(law_by_name("tsuji"), with_map), invalid_parameter);
}

TEST(evaluate, exact_forms_and_relative_bounds) {
  // Tsuji at g = 0, gamma = 1e-20: a closed form; relative on 1 - e = sqrt(5) pi gamma / 4 (1 + O(gamma)).
  evaluate_options relative;
  relative.relative = true;
  const evaluation<double> t = evaluate(law_by_name("tsuji"), 1e-20, 0.0, 1e-10, relative);
  EXPECT_EQ(t.method, evaluation_method::exact);
  const double leading = std::sqrt(5.0) * 3.141592653589793 / 4 * 1e-20;
  EXPECT_NEAR(t.one_minus_e / leading, 1.0, 1e-10);
  EXPECT_EQ(t.e, 1.0);  // e itself rounds to 1 in double; 1 - e keeps its digits
  // Linear law under load: exact, with T_f, against the closed form at 50 digits.
  const evaluation<double> lin = evaluate(law_by_name("linear"), 0.3, 0.25, 1e-12);
  EXPECT_EQ(lin.method, evaluation_method::exact);
  ASSERT_TRUE(lin.contact_time.has_value());
#if VISCOR_HAS_MPFR
  const auto ref = exact_cor(law_by_name("linear"), mpfr_50(0.3), mpfr_50(0.25));
  EXPECT_LE(abs(mpfr_50(lin.e) - ref->e), mpfr_50(lin.bound));
  // Kuwabara-Kono at gamma = 1e-12 under load, relative 1e-6 on 1 - e ~ 1.7e-12: the solve.
  const evaluation<double> kk = evaluate(law_by_name("kuwabara_kono"), 1e-12, 0.5, 1e-6, relative);
  const impact_result<mpfr_50> kk_ref = solve_impact(law_by_name("kuwabara_kono"), mpfr_50(1e-12), mpfr_50(0.5));
  EXPECT_LE(abs(mpfr_50(kk.one_minus_e) - kk_ref.one_minus_e), mpfr_50(kk.bound) * kk_ref.one_minus_e);
  EXPECT_LE(kk.bound, 1e-6);
#endif
  // gamma = 0: e = 1 exactly.
  const evaluation<double> zero = evaluate(law_by_name("hunt_crossley"), 0.0, 3.0, 1e-14);
  EXPECT_EQ(zero.e, 1.0);
  EXPECT_EQ(zero.method, evaluation_method::exact);
}

TEST(evaluate, rejects_bad_input) {
  const contact_law law = law_by_name("kuwabara_kono");
  EXPECT_THROW(evaluate(law, 0.1, 0.0, 0.0), invalid_parameter);
  EXPECT_THROW(evaluate(law, 0.1, 0.0, -1e-3), invalid_parameter);
  EXPECT_THROW(evaluate(law, 0.1, 0.0, std::nan("")), invalid_parameter);
  EXPECT_THROW(evaluate(law, -0.1, 0.0, 1e-3), invalid_parameter);
  try {
    evaluate(law, 0.1, 0.0, 1e-20);
    ADD_FAILURE() << "a 1e-20 bound does not fit in double";
  } catch (const precision_unavailable& e) {
    EXPECT_NE(std::string(e.what()).find("tolerance 1.00e-20"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace viscor
