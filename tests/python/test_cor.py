"""viscor.cor against independent values: the linear law's closed form (written in
viscor_test_support from the model, evaluated with mpmath), the committed certified
table reference_data/cor_report_grid.csv, and the CLI binary (another front end)."""

import decimal
import fractions
import json
import subprocess
import unittest

import viscor
from viscor_test_support import CLI, linear_law_e, mpmath, reference_rows


def agreeing_digits(a, b):
    """Significant decimal digits on which a and b (Decimals) agree."""
    if a == b:
        return 1000
    rel = abs(a - b) / abs(b)
    return int(-rel.log10())


@unittest.skipIf(mpmath is None, "needs mpmath (python3-mpmath)")
class LinearLawClosedForm(unittest.TestCase):
    def test_fifty_digits_against_the_closed_form(self):
        for gamma, g in (("0.05", "0"), ("0.3", "0"), ("0.05", "0.3"), ("1/3", "1/10"), ("0.001", "0.05")):
            with self.subTest(gamma=gamma, g=g):
                r = viscor.cor("linear", gamma, g, digits=50)
                e, t = linear_law_e(gamma, g)
                ref_e = decimal.Decimal(mpmath.nstr(e, 60, strip_zeros=False))
                ref_t = decimal.Decimal(mpmath.nstr(t, 60, strip_zeros=False))
                self.assertEqual(r.outcome, "rebound")
                self.assertEqual(r.working_digits, 50)
                self.assertEqual(r.digits, 50)  # the older name
                self.assertGreaterEqual(agreeing_digits(r.decimal("e"), ref_e), 45, (r.e, ref_e))
                self.assertGreaterEqual(agreeing_digits(r.decimal("contact_time"), ref_t), 45)
                one_minus = decimal.Context(prec=100).subtract(1, ref_e)
                self.assertGreaterEqual(agreeing_digits(r.decimal("one_minus_e"), one_minus), 43)

    def test_alpha_beta_as_fractions_equal_the_named_law(self):
        named = viscor.cor("kuwabara_kono", "0.05", "1", digits=30)
        custom = viscor.cor(gamma=decimal.Decimal("0.05"), g=1, digits=30, alpha=fractions.Fraction(3, 2),
                            beta="3/2")
        self.assertEqual(named.e_exact, custom.e_exact)
        self.assertEqual(custom.law.name, "")

    def test_float_is_its_exact_binary_value(self):
        as_float = viscor.cor("linear", 0.05, 0, digits=40)
        exact_binary = viscor.cor("linear", str(decimal.Decimal(0.05)), 0, digits=40)
        as_decimal = viscor.cor("linear", "0.05", 0, digits=40)
        self.assertEqual(as_float.e_exact, exact_binary.e_exact)
        self.assertNotEqual(as_float.e_exact, as_decimal.e_exact)


class CertifiedTable(unittest.TestCase):
    """Rows of the committed certified table (its sidecar records how it was made)."""

    def test_rows_of_cor_report_grid(self):
        rows = [r for r in reference_rows() if r["law"] in ("tsuji", "kuwabara_kono", "hunt_crossley")
                and r["gamma"] in ("0.0137", "0.05", "0.0999") and r["outcome"] == "rebound"]
        self.assertGreaterEqual(len(rows), 9)
        for row in rows:
            with self.subTest(law=row["law"], gamma=row["gamma"], g=row["g"]):
                r = viscor.cor(row["law"], row["gamma"], row["g"], digits=40)
                certified = int(row["digits"])
                # The row is certified to `certified` digits; a 40-digit solve must agree to them less one.
                self.assertGreaterEqual(agreeing_digits(r.decimal("e"), decimal.Decimal(row["e"])), certified - 1)
                self.assertGreaterEqual(agreeing_digits(r.decimal("one_minus_e"), decimal.Decimal(row["one_minus_e"])),
                                        certified - 1)

    def test_certify_agrees_with_the_table(self):
        row = next(r for r in reference_rows() if r["law"] == "hunt_crossley" and r["gamma"] == "0.05"
                   and r["g"] == "0.05")
        r = viscor.cor("hunt_crossley", "0.05", "0.05", digits=30, certify=True)
        self.assertTrue(r.certified.outcome_certified)
        self.assertGreaterEqual(r.certified.certified_digits, 20)
        self.assertEqual(r.certified.digits, r.certified.certified_digits)  # the older name
        # The certified value is printed rounded to its certified digits.
        self.assertGreaterEqual(agreeing_digits(r.certified.decimal("e"), decimal.Decimal(row["e"])),
                                r.certified.certified_digits - 1)
        self.assertEqual(len(r.certified.computations), 3)


@unittest.skipUnless(CLI, "VISCOR_CLI (the viscor binary) not set")
class SameDigitsAsTheCli(unittest.TestCase):
    def test_acceptance_point(self):
        out = subprocess.run([CLI, "cor", "--model", "kuwabara_kono", "--gamma", "0.05", "--g", "1", "--digits", "50",
                              "--json"], check=True, capture_output=True, text=True).stdout
        cli = json.loads(out)
        r = viscor.cor("kuwabara_kono", "0.05", "1", digits=50)
        for field in ("e", "one_minus_e", "contact_time", "max_compression", "time_of_max_compression",
                      "error_estimate", "gamma", "g"):
            self.assertEqual(getattr(r, field + "_exact"), cli[field], field)  # the exact decimal, digit for digit
            self.assertEqual(getattr(r, field), float(cli[field]), field)      # and the number nearest to it
        for field in ("outcome", "method"):
            self.assertEqual(getattr(r, field), cli[field], field)
        self.assertEqual(r.precision.to_dict(), cli["precision"])
        self.assertEqual(r.steps, cli["steps"])
        self.assertEqual(set(r.keys()), set(cli.keys()))
        text = subprocess.run([CLI, "cor", "--model", "kuwabara_kono", "--gamma", "0.05", "--g", "1", "--digits",
                               "50"], check=True, capture_output=True, text=True).stdout
        self.assertIn("e          " + r.e_exact + "\n", text)

    def test_certified_digits_asked_for(self):
        """certified_digits=N: the CLI's --certified-digits N, the same precision runs and
        digits; at least N certified, and the working precision chosen, not given."""
        for wanted in (30, 40):
            with self.subTest(certified_digits=wanted):
                out = subprocess.run([CLI, "cor", "--model", "hunt_crossley", "--gamma", "0.0245", "--g", "1",
                                      "--certified-digits", str(wanted), "--json"],
                                     check=True, capture_output=True, text=True).stdout
                cli = json.loads(out)
                r = viscor.cor("hunt_crossley", "0.0245", "1", certified_digits=wanted)
                self.assertGreaterEqual(r.certified.certified_digits, wanted)
                self.assertEqual(r.certified_digits_goal, wanted)
                self.assertEqual([p.to_dict() for p in r.precision_runs], cli["precision_runs"])
                self.assertEqual(r.certified.e_exact, cli["certified"]["e"])
                self.assertEqual(r.e_exact, cli["e"])
        with self.assertRaises(viscor.InvalidParameter):
            viscor.cor("hunt_crossley", "0.0245", "1", digits=40, certified_digits=30)
        with self.assertRaisesRegex(viscor.InvalidParameter, "certified_digits must be from 1 to"):
            viscor.cor("hunt_crossley", "0.0245", "1", certified_digits=0)
        with self.assertRaises(TypeError):
            viscor.cor("hunt_crossley", "0.0245", "1", certified_digits=30.0)


class ResultObject(unittest.TestCase):
    def test_conversions(self):
        r = viscor.cor("tsuji", "0.1", "0.5", digits=50)
        self.assertIsInstance(r.e, float)  # a number: arithmetic and comparisons work
        self.assertEqual(r.e * 2, 2 * float(decimal.Decimal(r.e_exact)))
        self.assertTrue(0.6 < r.e < 0.7)
        self.assertIsInstance(r.e_exact, str)
        self.assertEqual(r["e"], r.e)
        self.assertEqual(r.exact("e"), r.e_exact)
        self.assertEqual(r.to_dict()["e"], r.e_exact)
        self.assertEqual(r.decimal("e"), decimal.Decimal(r.e_exact))
        self.assertEqual(float(r.decimal("e")), r.e)  # the float nearest to the exact value
        self.assertIsInstance(r.decimal("e"), decimal.Decimal)
        self.assertAlmostEqual(r.e + r.one_minus_e, 1.0, places=14)
        self.assertIsInstance(r.contact_time, float)
        self.assertEqual(r.outcome, "rebound")  # text stays text
        self.assertEqual(r.law.name, "tsuji")
        self.assertEqual(r.law.alpha, "3/2")
        self.assertEqual(r.precision.digits, 50)
        self.assertIsInstance(r.steps, int)
        self.assertIn("error_estimate", r)
        with self.assertRaises(AttributeError):
            r.no_such_field
        with self.assertRaises(AttributeError):
            r.e = "1"
        if mpmath is not None:
            x = r.mpf("e")
            self.assertEqual(x.context.prec, 53)  # mpmath's global precision is left alone
            with mpmath.workdps(60):
                self.assertEqual(mpmath.nstr(x, 50), mpmath.nstr(mpmath.mpf(r.e_exact), 50))

    def test_stick(self):
        r = viscor.cor("hertz_linear_damping", "1.5", "1", digits=20)
        self.assertEqual(r.outcome, "stick")
        self.assertEqual(r.decimal("e"), 0)
        self.assertIn("stop_overlap", r)

    def test_a_rebound_the_energy_rules_out_is_undecided(self):
        # Hunt-Crossley, gamma 1e-30, g 1e12 in double: the Taylor solver returned
        # e = 288 (a stick at 20 digits and more); e > 1 cannot be, so: undecided.
        r = viscor.cor("hunt_crossley", "1e-30", "1e12")
        self.assertNotEqual(r.outcome, "rebound")
        self.assertLessEqual(r.decimal("e"), 1)


if __name__ == "__main__":
    unittest.main()
