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
        self.assertGreater(len(check.cells), 10)
        self.assertLessEqual(float(check.overall.max_abs_e), 1e-9)
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

    def test_bad_calls(self):
        with self.assertRaises(TypeError):
            viscor.compare("not a function", "kuwabara_kono", 1e-3)
        with self.assertRaises(ValueError):
            viscor.compare(accurate, "kuwabara_kono", 1e-3, quantity="e2")
        with self.assertRaises(ValueError):
            viscor.compare(lambda gamma, g: gamma[:3], "kuwabara_kono", 1e-3)


if __name__ == "__main__":
    unittest.main()
