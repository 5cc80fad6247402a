"""viscor.compare: a formula of one's own against the certified tables (docs/formulas.md).

The formula here is viscor.evaluate at a tolerance of 1e-12 (independent of the
tables: solves and error maps in double), once as it is and once made wrong by
1e-3 in one cell; the checks must pass and fail accordingly, and the failure must
name a point of that cell."""

import os
import tempfile
import unittest

import viscor
from viscor_test_support import numpy as np, skip_or_fail


def accurate(gamma, g):
    return viscor.evaluate("kuwabara_kono", gamma, g, tol=1e-12).e


def wrong_in_one_cell(gamma, g):
    inside = (gamma >= 1e-4) & (gamma <= 2e-4) & (g >= 0.01) & (g <= 0.1)
    return accurate(gamma, g) + np.where(inside, 1e-3, 0.0)


class Compare(unittest.TestCase):
    def setUp(self):
        if np is None:
            skip_or_fail(self, "numpy")

    def test_pass_within_tolerance(self):
        check = viscor.compare(accurate, "kuwabara_kono", 1e-9, region=(0, 1e-3, 0, 10))
        self.assertTrue(check, str(check))
        self.assertEqual(check.reason, "")
        self.assertGreater(len(check.cells), 10)
        self.assertLessEqual(check.overall.max_abs_e, 1e-9)  # a number, not a string
        self.assertIsInstance(check.overall.max_abs_e, float)
        self.assertEqual(check.coverage.cells_judged, len(check.cells))
        self.assertGreaterEqual(check.coverage.cells_in_region, check.coverage.cells_judged)
        self.assertIn("coverage   ", str(check))
        worst = check.column("max_abs_e")
        self.assertEqual(worst.shape, (len(check.cells),))
        self.assertEqual(worst.max(), float(check.overall.max_abs_e))
        self.assertTrue(check.column("pass").all())

    def test_fail_names_the_worst_point(self):
        check = viscor.compare(wrong_in_one_cell, "kuwabara_kono", 1e-9, region=(0, 1e-3, 0, 10))
        self.assertFalse(check)
        worst = check.overall.worst
        self.assertTrue(1e-4 <= float(worst.gamma) <= 2e-4 and 0.01 <= float(worst.g) <= 0.1, worst)
        self.assertIn("fails      gamma 1e-4..2e-4, g 0.01..0.1", str(check))
        failing = [c for c in check.cells if not c.get("pass")]
        self.assertTrue(all(float(c.gamma_lo) <= 2e-4 and float(c.gamma_hi) >= 1e-4 for c in failing), failing)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "map.png")
            check.plot(path)
            self.assertGreater(os.path.getsize(path), 1000)

    def test_points_outside_the_tables_against_evaluate(self):
        gamma = np.array([0.003, 0.03])
        r = viscor.compare(accurate, "kuwabara_kono", 1e-6, gamma=gamma, g=0.7)
        self.assertEqual(r.abs_error.shape, (2,))
        self.assertTrue(np.all(r.abs_error <= 1e-6))
        self.assertEqual(set(r.bound_kind), {"empirical"})
        self.assertTrue(r, r.reason)
        self.assertTrue(r.passed.all())

    def test_every_check_type_is_false_when_its_formula_is_wrong(self):
        # One truth rule: bool(check) is the verdict, for points as for cells.
        zero = viscor.compare(lambda ga, g: 0 * ga, "kuwabara_kono", 1e-3, gamma=[0.01], g=[0.1])
        self.assertFalse(zero)
        self.assertIn("1 of 1 point(s) fail", zero.reason)
        cells = viscor.compare(lambda ga, g: 0 * ga, "kuwabara_kono", 1e-3, region=(0, 1e-3, 0, 10))
        self.assertFalse(cells)
        self.assertIn("cell(s) fail", cells.reason)

    def test_a_check_that_judged_nothing_is_false_and_says_why(self):
        none = viscor.compare(accurate, "kuwabara_kono", 1e-3, region=(0.3, 0.4, None, None))  # between two edges
        self.assertFalse(none)
        self.assertEqual(none.coverage.cells_judged, 0)
        self.assertIn("no cell judged: the region holds no cell of the map", none.reason)
        self.assertIn("no cell judged", str(none))
        no_points = viscor.compare(lambda ga, g: ga, "kuwabara_kono", 1e-3, gamma=[], g=[])
        self.assertFalse(no_points)
        self.assertIn("no point judged", no_points.reason)

    def test_region_bounds_and_tolerances_as_the_cli_refuses_them(self):
        for bound in (float("nan"), float("inf"), "0x10", "1e-400", "nan"):
            with self.subTest(bound=bound):
                with self.assertRaisesRegex(viscor.InvalidParameter, "gamma_max"):
                    viscor.compare(accurate, "kuwabara_kono", 1e-3, region=(0, bound, 0, 10))
        with self.assertRaisesRegex(viscor.InvalidParameter, "the region is empty: gamma_min = 0.01 is not below"):
            viscor.compare(accurate, "kuwabara_kono", 1e-3, region=(0.01, 0.001, 0, 10))
        for tol in (1, 2.5, -1e-3, "1e-400", float("nan")):
            with self.subTest(tol=tol):
                with self.assertRaisesRegex(viscor.InvalidParameter, "tolerance"):
                    viscor.compare(accurate, "kuwabara_kono", tol, region=(0, 1e-3, 0, 10))
                with self.assertRaisesRegex(viscor.InvalidParameter, "tolerance"):
                    viscor.compare(accurate, "kuwabara_kono", tol, gamma=[0.01], g=[0.1])

    def test_bad_calls(self):
        with self.assertRaises(TypeError):
            viscor.compare("not a function", "kuwabara_kono", 1e-3)
        with self.assertRaises(ValueError):
            viscor.compare(accurate, "kuwabara_kono", 1e-3, quantity="e2")
        with self.assertRaises(ValueError):
            viscor.compare(lambda gamma, g: gamma[:3], "kuwabara_kono", 1e-3)


if __name__ == "__main__":
    unittest.main()
