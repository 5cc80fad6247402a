// Closed forms of closed_form.hpp: Kuwabara-Kono constants against independently
// computed values, the Beta closed forms against the quadrature of integrals.hpp,
// exact values for the linear law, and input validation.
//
// Reference digits: the short strings are reference values computed
// independently of this code; the long strings were computed with mpmath 1.3.0 at 130 digits
// from the Beta-function formulas, and for I(0), Q(0) checked there against mpmath's
// own quadrature of the defining integrals (agreement to 66+ digits), e.g.
//   C0 = b ((a+1)/2)^((b-a-1)/(a+1)) beta(b/(a+1), 3/2),  a = b = 3/2.
#include <viscor/approx/closed_form.hpp>
#include <viscor/approx/integrals.hpp>

#include "test_utils.hpp"

#include <boost/math/constants/constants.hpp>
#include <gtest/gtest.h>

#include <string>

namespace {

using viscor::test::constant;
using viscor::test::ulps;

// mpmath, 110 significant digits.
const std::string kk_C0 =
    "1.7301732871429331986958511586484228119225183519160848668064333734489001907275802279327211903901958455877890867";
const std::string kk_C =
    "4.4039857765502876705353224083292423182433777412254381306671907759615576190200105270811556532946120589582065935";
const std::string kk_gc =
    "0.30522010936920793374825927566774758602561533162860768417612905752288264810497454708505416550410055602795724514";
const std::string kk_C2 =
    "-1.7960997621257896640630878344794568090593942566954675502239513597277300590015337560638058796088458537465228619";
const std::string sp_c1 =
    "-1.1534488580952887991305674390989485412816789012773899112042889156326001271517201519551474602601305637251927245";
const std::string sp_c2 =
    "0.79826656094479540625026125976864747069306411408687446676620060432343558177845944713946927982615371277623238308";

struct law_reference {
  const char* name;
  std::string i0, q0;
};
const law_reference law_references[] = {
    {"linear",
     "1.5707963267948966192313216916397514420985846996875529104874722961539082031431044993140174126710585339910740433",
     "1.5707963267948966192313216916397514420985846996875529104874722961539082031431044993140174126710585339910740433"},
    {"hertz_linear_damping",
     "1.7878141442883572691866278031208224658630608325244105413204325446170659311218270663565920047986334648897311319",
     "1.6090327298595215422679650228087402192767547492719694871883892901553593380096443597209328043187701184007580187"},
    {"tsuji",
     "1.4049629462081452786312749286409789598933018374134404839979442052384283761238376410208284830731534480430142594",
     "1.4049629462081452786312749286409789598933018374134404839979442052384283761238376410208284830731534480430142594"},
    {"kuwabara_kono",
     "1.1534488580952887991305674390989485412816789012773899112042889156326001271517201519551474602601305637251927245",
     "1.2687937439048176790436241830088433954098467914051289023247178071958601398668921671506622062861436200977119969"},
    {"hunt_crossley", "0.66666666666666666666666666666666666666666666666666666666666666666666666666666666666666666666666666666667",
     "1"},
};

template <class Real>
class ClosedForm : public ::testing::Test {};

using Reals = ::testing::Types<double, long double, viscor::quad, viscor::mpfr_50, viscor::mpfr_100>;
TYPED_TEST_SUITE(ClosedForm, Reals);

TYPED_TEST(ClosedForm, KuwabaraKonoConstantsMatchIndependentValues) {
  using Real = TypeParam;
  const Real a = Real(3) / 2, b = Real(3) / 2;
  const Real tol = ulps<Real>(32);  // mpfr_50: 3e-49, mpfr_100: 4e-99
  VISCOR_EXPECT_REL(viscor::coefficient_C0(a, b), constant<Real>(kk_C0), tol);
  VISCOR_EXPECT_REL(viscor::coefficient_C1(a, b), Real(3), tol);
  VISCOR_EXPECT_REL(viscor::coefficient_C(a, b), constant<Real>(kk_C), tol);
  VISCOR_EXPECT_REL(viscor::coefficient_C2_at_zero(a, b), constant<Real>(kk_C2), tol);
  VISCOR_EXPECT_REL(viscor::schwager_poschel_c1<Real>(), constant<Real>(sp_c1), tol);
  VISCOR_EXPECT_REL(viscor::schwager_poschel_c2<Real>(), constant<Real>(sp_c2), tol);
  VISCOR_EXPECT_REL(viscor::schwager_poschel_C2<Real>(), constant<Real>(kk_C2), tol);
  EXPECT_EQ(viscor::large_g_exponent(a, b), Real(11) / 6);
  // g_c = 0.30522... gamma^(-6/11), eq. (24).
  VISCOR_EXPECT_REL(viscor::critical_g(a, b, Real(1)), constant<Real>(kk_gc), tol);
  using std::pow;
  const Real gamma = Real(1) / 64;
  VISCOR_EXPECT_REL(viscor::critical_g(a, b, gamma), Real(constant<Real>(kk_gc) * pow(gamma, -Real(6) / 11)), tol);
}

TYPED_TEST(ClosedForm, IssueValuesToTheirPrintedDigits) {
  using Real = TypeParam;
  const Real a = Real(3) / 2, b = Real(3) / 2;
  // Values computed independently of this code, good to their last printed digit.
  const Real tol = std::max(ulps<Real>(32), Real(1e-27));
  VISCOR_EXPECT_REL(viscor::coefficient_C0(a, b), constant<Real>("1.730173287142933198695851158"), tol);
  VISCOR_EXPECT_REL(viscor::coefficient_C(a, b), constant<Real>("4.403985776550287670535"), std::max(tol, Real(1e-21)));
  VISCOR_EXPECT_REL(viscor::critical_g(a, b, Real(1)), constant<Real>("0.3052201093692079337"),
                    std::max(tol, Real(1e-18)));
  VISCOR_EXPECT_REL(viscor::coefficient_C2_at_zero(a, b), constant<Real>("-1.796099762125789664063"),
                    std::max(tol, Real(1e-21)));
}

TYPED_TEST(ClosedForm, IntegralsAtZeroMatchIndependentValues) {
  using Real = TypeParam;
  for (const auto& ref : law_references) {
    SCOPED_TRACE(ref.name);
    const auto law = viscor::law_by_name(ref.name);
    const Real a = law.alpha.value<Real>(), b = law.beta.value<Real>();
    const Real tol = ulps<Real>(32);
    VISCOR_EXPECT_REL(viscor::integral_I_at_zero(a, b), constant<Real>(ref.i0), tol);
    VISCOR_EXPECT_REL(viscor::integral_Q_at_zero(a, b), constant<Real>(ref.q0), tol);
    // The defining relations C0 = beta I(0), C1 = beta dI/dg(0), C2 = -beta^2 I(0) (Q(0) - I(0)/2).
    const Real i0 = viscor::integral_I_at_zero(a, b), q0 = viscor::integral_Q_at_zero(a, b);
    VISCOR_EXPECT_REL(viscor::coefficient_C0(a, b), Real(b * i0), tol);
    VISCOR_EXPECT_REL(viscor::coefficient_C1(a, b), Real(b * viscor::integral_dI_dg_at_zero(a, b)), tol);
    VISCOR_EXPECT_REL(viscor::coefficient_C2_at_zero(a, b), Real(-b * b * i0 * (q0 - i0 / 2)), tol);
  }
}

TYPED_TEST(ClosedForm, LinearLawIsKnownExactly) {
  // alpha = beta = 1 at g = 0: e = exp(-xi pi/omega) = 1 - (pi/2) gamma + (pi^2/8) gamma^2 + O(gamma^3),
  // so C0 = pi/2, C2 = -pi^2/8; F = 1 - u^2 gives I(0) = Q(0) = pi/2, dI/dg(0) = 2 (circle segments).
  using Real = TypeParam;
  const Real pi = boost::math::constants::pi<Real>(), one = 1, tol = ulps<Real>(16);
  VISCOR_EXPECT_REL(viscor::coefficient_C0(one, one), Real(pi / 2), tol);
  VISCOR_EXPECT_REL(viscor::coefficient_C2_at_zero(one, one), Real(-pi * pi / 8), tol);
  VISCOR_EXPECT_REL(viscor::integral_dI_dg_at_zero(one, one), Real(2), tol);
  VISCOR_EXPECT_REL(viscor::coefficient_C1(one, one), Real(2), tol);
  // Large g, eq. (23): C = 2 sqrt(2) 2^(3/2) B(3/2, 3/2) = 8 (pi/8) = pi, p = 2.
  VISCOR_EXPECT_REL(viscor::coefficient_C(one, one), pi, tol);
  EXPECT_EQ(viscor::large_g_exponent(one, one), Real(2));
}

TYPED_TEST(ClosedForm, BetaClosedFormsAgreeWithQuadrature) {
  using Real = TypeParam;
  for (const auto& n : viscor::named_laws) {
    SCOPED_TRACE(std::string(n.name));
    const auto law = viscor::law_by_name(n.name);
    const Real a = law.alpha.value<Real>(), b = law.beta.value<Real>();
    const auto v = viscor::integrals_IQ(a, b, Real(0));
    const Real tol = ulps<Real>(256);
    VISCOR_EXPECT_REL(v.I, viscor::integral_I_at_zero(a, b), tol);
    VISCOR_EXPECT_REL(v.Q, viscor::integral_Q_at_zero(a, b), tol);
    VISCOR_EXPECT_REL(viscor::integral_dI_dg(a, b, Real(0)), viscor::integral_dI_dg_at_zero(a, b), tol);
  }
}

TYPED_TEST(ClosedForm, CriticalGammaInvertsCriticalG) {
  using Real = TypeParam;
  for (const auto& n : viscor::named_laws) {
    SCOPED_TRACE(std::string(n.name));
    const auto law = viscor::law_by_name(n.name);
    const Real a = law.alpha.value<Real>(), b = law.beta.value<Real>();
    for (const Real gamma : {Real(1) / 1000, Real(1) / 10, Real(2)}) {
      const Real gc = viscor::critical_g(a, b, gamma);
      VISCOR_EXPECT_REL(viscor::critical_gamma(a, b, gc), gamma, ulps<Real>(64));
      // Eq. (24): 2 gamma C g_c^p = 1.
      using std::pow;
      VISCOR_EXPECT_REL(Real(2 * gamma * viscor::coefficient_C(a, b) * pow(gc, viscor::large_g_exponent(a, b))),
                        Real(1), ulps<Real>(64));
    }
  }
}

TYPED_TEST(ClosedForm, ContactLawOverloadsAgree) {
  using Real = TypeParam;
  const auto law = viscor::law_by_name("tsuji");
  const Real a = Real(3) / 2, b = Real(5) / 4;
  EXPECT_EQ(viscor::coefficient_C0<Real>(law), viscor::coefficient_C0(a, b));
  EXPECT_EQ(viscor::coefficient_C<Real>(law), viscor::coefficient_C(a, b));
  EXPECT_EQ(viscor::critical_g(law, Real(1) / 10), viscor::critical_g(a, b, Real(1) / 10));
  const viscor::closed_form_coefficients<Real> all(law);
  EXPECT_EQ(all.C2, viscor::coefficient_C2_at_zero(a, b));
  EXPECT_EQ(all.Q0, viscor::integral_Q_at_zero(a, b));
}

TEST(ClosedFormErrors, BadInputIsRejectedWithTheValue) {
  try {
    viscor::critical_g(1.5, 1.5, 0.0);
    FAIL() << "gamma = 0 accepted";
  } catch (const viscor::invalid_parameter& e) {
    EXPECT_NE(std::string(e.what()).find("gamma"), std::string::npos) << e.what();
  }
  EXPECT_THROW(viscor::critical_g(1.5, 1.5, -0.1), viscor::invalid_parameter);
  EXPECT_THROW(viscor::critical_gamma(1.5, 1.5, -2.0), viscor::invalid_parameter);
  EXPECT_THROW(viscor::critical_gamma(1.5, 1.5, 0.0), viscor::invalid_parameter);
  try {
    viscor::coefficient_C0(0.5, 1.5);
    FAIL() << "alpha = 0.5 accepted";
  } catch (const viscor::invalid_parameter& e) {
    EXPECT_NE(std::string(e.what()).find("alpha = 5.0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(viscor::coefficient_C(1.5, std::nan("")), viscor::invalid_parameter);
}

}  // namespace
