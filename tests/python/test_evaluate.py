"""viscor.evaluate over NumPy arrays: values within their empirical bounds of the
linear law's closed form and of the committed certified table; shapes and
broadcasting; bad points; concurrent calls from Python threads give the serial
results, which are themselves checked against the exact values."""

import math
import os
import subprocess
import sys
import tempfile
import threading
import unittest

import viscor
from viscor_test_support import numpy as np, reference_rows, skip_or_fail, write_synthetic_surrogate


def linear_e_at_zero_load(gamma):
    """e of the linear law at g = 0: exp(-gamma pi / (2 w)), w = sqrt(1 - gamma^2 / 4)."""
    w = np.sqrt(1 - gamma**2 / 4)
    return np.exp(-gamma * math.pi / (2 * w))


@unittest.skipIf(np is None, "needs NumPy (python3-numpy)")
class Values(unittest.TestCase):
    def test_linear_law_closed_form(self):
        gamma = np.linspace(0, 1.5, 301)
        for tol in (1e-4, 1e-8, 1e-12):
            with self.subTest(tol=tol):
                r = viscor.evaluate("linear", gamma, 0.0, tol)
                exact = linear_e_at_zero_load(gamma)
                self.assertTrue(np.all(r.empirical_bound <= tol))
                # The bound is empirical; the closed form is exact (up to its double rounding).
                self.assertTrue(np.all(np.abs(r.e - exact) <= r.empirical_bound + 4e-16),
                                np.max(np.abs(r.e - exact) - r.empirical_bound))
                self.assertTrue(np.all(r.outcome == 0))

    def test_certified_table(self):
        rows = [row for row in reference_rows() if row["law"] in ("hertz_linear_damping", "kuwabara_kono")
                and row["index"].endswith("7")]
        self.assertGreater(len(rows), 300)
        for law in ("hertz_linear_damping", "kuwabara_kono"):
            mine = [row for row in rows if row["law"] == law]
            gamma = np.array([float(row["gamma"]) for row in mine])
            g = np.array([float(row["g"]) for row in mine])
            ref = np.array([float(row["e"]) for row in mine])
            for tol in (1e-4, 1e-9):
                with self.subTest(law=law, tol=tol):
                    r = viscor.evaluate(law, gamma, g, tol)
                    # gamma and g of the table are decimals; in double they move by 1 ulp,
                    # which moves e by far less than 1e-15.
                    err = np.abs(r.e - ref)
                    self.assertTrue(np.all(err <= r.empirical_bound + 1e-15), np.max(err - r.empirical_bound))

    def test_relative_bound(self):
        gamma = np.array([1e-6, 1e-4, 1e-2])
        r = viscor.evaluate("linear", gamma, 0, 1e-6, relative=True)
        exact_one_minus_e = -np.expm1(-gamma * math.pi / (2 * np.sqrt(1 - gamma**2 / 4)))
        rel = np.abs(r.one_minus_e - exact_one_minus_e) / exact_one_minus_e
        self.assertTrue(np.all(rel <= r.empirical_bound + 1e-15))

    def test_methods_are_named(self):
        r = viscor.evaluate("kuwabara_kono", np.array([0.0, 0.05, 0.05]), np.array([0.0, 0.0, 1.0]), 1e-4,
                            surrogate=None)
        names = [viscor.EVALUATION_METHODS[m] for m in r.method]
        self.assertEqual(names[0], "exact")  # gamma = 0: the closed form
        for n in names:
            self.assertIn(n, viscor.EVALUATION_METHODS)


@unittest.skipIf(np is None, "needs NumPy (python3-numpy)")
class Shapes(unittest.TestCase):
    def test_broadcasting(self):
        gamma = np.linspace(0.01, 0.1, 4).reshape(4, 1)
        g = np.array([0.0, 0.5, 1.0])
        r = viscor.evaluate("tsuji", gamma, g, 1e-6)
        for field in r:
            self.assertEqual(field.shape, (4, 3))
        self.assertEqual(r.method.dtype, np.int8)
        # Each cell equals the evaluation of its own point.
        single = viscor.evaluate("tsuji", gamma[2, 0], g[1], 1e-6)
        self.assertEqual(single.e.shape, ())
        self.assertEqual(float(single.e), r.e[2, 1])

    def test_scalars_lists_and_tolerance_arrays(self):
        r = viscor.evaluate("linear", [0.1, 0.2], 0, [1e-4, 1e-10])
        self.assertEqual(r.e.shape, (2,))
        self.assertLessEqual(r.empirical_bound[1], 1e-10)

    def test_non_contiguous_and_integer_input(self):
        gamma = np.linspace(0, 0.2, 20)[::3]
        r = viscor.evaluate("linear", gamma, np.zeros(7, dtype=np.int64), 1e-8)
        self.assertTrue(np.allclose(r.e, linear_e_at_zero_load(gamma), atol=1e-8, rtol=0))

    def test_empty(self):
        r = viscor.evaluate("linear", np.zeros((0, 3)), 0, 1e-6)
        self.assertEqual(r.e.shape, (0, 3))

    def test_shapes_that_do_not_broadcast(self):
        with self.assertRaises(ValueError):
            viscor.evaluate("linear", np.zeros(3), np.zeros(4), 1e-6)

    def test_bad_points_are_named(self):
        with self.assertRaises(viscor.InvalidParameter) as caught:
            viscor.evaluate("tsuji", np.array([0.1, 0.2, np.nan, 0.3]), 0, 1e-6)
        self.assertIn("point 2", str(caught.exception))
        with self.assertRaises(ValueError) as caught:
            viscor.evaluate("tsuji", np.array([0.1, -0.2]), 0, 1e-6)
        self.assertIn("point 1", str(caught.exception))
        with self.assertRaises(ValueError):
            viscor.evaluate("tsuji", 0.1, 0, 0.0)
        with self.assertRaises(ValueError):
            viscor.evaluate("tsuji", 0.1, 0, 1e-30)  # below what double holds
        with self.assertRaises(TypeError):
            viscor.evaluate("tsuji", "abc", 0, 1e-6)
        with self.assertRaises(ValueError):
            viscor.evaluate(None, 0.1, 0, 1e-6, alpha="1/2", beta="1")


@unittest.skipIf(np is None, "needs NumPy (python3-numpy)")
class SurrogatePlumbing(unittest.TestCase):
    """A synthetic surrogate (values known by construction, deliberately not the true
    e) shows which path each point took; tests/python/test_commands.py checks the
    committed surrogates against certified tables when they exist."""

    def test_used_where_its_bound_meets_tol_and_in_domain(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = write_synthetic_surrogate(os.path.join(tmp, "linear.surrogate"), G=0.5, abs_e=1e-3)
            s = viscor.Surrogate(path)
            self.assertTrue(s.in_domain(0.1, 0.5))
            self.assertEqual(s.error_bound["abs_e"], 1e-3)
            gamma = np.array([0.1, 0.3, 0.1, 0.8])
            g = np.array([0.0, 0.5, 0.0, 0.0])
            tol = np.array([1e-2, 1e-2, 1e-6, 1e-2])
            r = viscor.evaluate("linear", gamma, g, tol, surrogate=path)
            names = [viscor.EVALUATION_METHODS[m] for m in r.method]
            self.assertEqual(names[:2], ["surrogate", "surrogate"])
            self.assertNotEqual(names[2], "surrogate")  # its bound 1e-3 misses tol 1e-6
            self.assertNotEqual(names[3], "surrogate")  # gamma = 0.8 is outside its domain
            synthetic = np.sqrt(1 - 0.5 * gamma)
            self.assertTrue(np.allclose(r.e[:2], synthetic[:2], rtol=0, atol=1e-15))
            self.assertTrue(np.all(r.empirical_bound[:2] == 1e-3))
            true_e = linear_e_at_zero_load(gamma[[2, 3]])
            self.assertTrue(np.all(np.abs(r.e[[2, 3]] - true_e) <= r.empirical_bound[[2, 3]] + 4e-16))
            self.assertEqual(float(s(0.3, 0.5)["e"]), r.e[1])
            with self.assertRaises(viscor.ParseError):
                with open(os.path.join(tmp, "bad.surrogate"), "w") as f:
                    f.write("viscor-cor-surrogate 1\nlaw linear 1 1\ndomain x\n")
                viscor.Surrogate(os.path.join(tmp, "bad.surrogate"))

    def test_unverified_or_damaged_is_refused(self):
        gamma, g, tol = np.array([0.1, 0.3]), np.array([0.0, 0.5]), np.array([1e-2, 1e-2])
        with tempfile.TemporaryDirectory() as tmp:
            verified = write_synthetic_surrogate(os.path.join(tmp, "verified.surrogate"))
            used = viscor.evaluate("linear", gamma, g, tol, surrogate=verified)
            self.assertEqual([viscor.EVALUATION_METHODS[m] for m in used.method], ["surrogate", "surrogate"])
            # The same file without a verification (safety factor 0) claims no bound: never used.
            unverified = write_synthetic_surrogate(os.path.join(tmp, "unverified.surrogate"), safety_factor=0)
            r = viscor.evaluate("linear", gamma, g, tol, surrogate=unverified)
            self.assertNotIn("surrogate", [viscor.EVALUATION_METHODS[m] for m in r.method])
            self.assertTrue(np.all(r.empirical_bound <= tol))
            # solved instead: the true e, not the synthetic sqrt(1 - G gamma)
            self.assertLessEqual(abs(r.e[0] - linear_e_at_zero_load(np.array([0.1]))[0]), r.empirical_bound[0] + 4e-16)
            self.assertGreater(abs(r.e[0] - np.sqrt(1 - 0.5 * 0.1)), 1e-3)
            # A damaged (truncated) file is refused with a parse error, not read in part.
            with open(verified) as f:
                text = f.read()
            damaged = os.path.join(tmp, "damaged.surrogate")
            with open(damaged, "w") as f:
                f.write(text[:len(text) // 2])
            with self.assertRaises(viscor.ParseError):
                viscor.evaluate("linear", gamma, g, tol, surrogate=damaged)

    def test_true_needs_a_committed_file(self):
        # A law given by its exponents has no committed surrogate.
        with self.assertRaises(viscor.InvalidParameter):
            viscor.evaluate(None, 0.1, 0.5, 1e-4, alpha="2", beta="3", surrogate=True)
        r = viscor.evaluate(None, 0.1, 0.5, 1e-4, alpha="2", beta="3")  # the default falls back silently
        self.assertNotEqual(viscor.EVALUATION_METHODS[int(r.method)], "surrogate")

    def test_default_uses_the_committed_surrogate(self):
        law = "kuwabara_kono"
        s = viscor.find_surrogate(law)
        if s is None:
            skip_or_fail(self, "no committed surrogate of " + law)
        gamma, g = np.array([0.05, 0.3]), np.array([1.0, -0.2])
        r = viscor.evaluate(law, gamma, g, 1e-10)
        self.assertEqual([viscor.EVALUATION_METHODS[m] for m in r.method], ["surrogate", "surrogate"])
        off = viscor.evaluate(law, gamma, g, 1e-10, surrogate=None)
        self.assertNotIn("surrogate", [viscor.EVALUATION_METHODS[m] for m in off.method])
        # Two different methods, each within its own bound of the other's value.
        self.assertTrue(np.all(np.abs(r.e - off.e) <= r.empirical_bound + off.empirical_bound))


@unittest.skipIf(np is None, "needs NumPy (python3-numpy)")
class PhysicalUnits(unittest.TestCase):
    """Physical inputs far outside their range are warned about as viscor.cor warns
    (on stderr, naming the point), and refused with strict=True."""

    BEAD = dict(m=2.05e-3, k=6.9716e9, gamma0=1e-6, gravity=9.81)

    def setUp(self):
        if np is None:
            skip_or_fail(self, "numpy")

    def test_a_speed_in_cm_per_s_is_warned_about_and_refused_when_strict(self):
        code = ("import viscor, numpy as np\n"
                f"viscor.evaluate('kuwabara_kono', v0=np.array([0.5, 50000.0]), **{self.BEAD!r})\n")
        run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("viscor: warning: evaluate: v0 (point 1) 50000 m/s is above", run.stderr)
        plain = subprocess.run([sys.executable, "-c", code.replace("50000.0", "0.7")], capture_output=True, text=True)
        self.assertEqual(plain.returncode, 0, plain.stderr)
        self.assertNotIn("warning", plain.stderr)
        with self.assertRaisesRegex(viscor.InvalidParameter, r"v0 \(point 1\) 50000 m/s"):
            viscor.evaluate("kuwabara_kono", v0=np.array([0.5, 50000.0]), strict=True, **self.BEAD)


class ThreadSafety(unittest.TestCase):
    def test_concurrent_calls_equal_the_serial_run(self):
        rng = np.random.default_rng(16)
        gamma = rng.uniform(0, 1.2, 2000)
        g = np.where(rng.uniform(size=2000) < 0.5, 0.0, rng.uniform(0, 0.5, 2000))
        serial = viscor.evaluate("linear", gamma, g, 1e-8, threads=1)
        # The serial run against the exact values where the closed form above applies (g = 0).
        zero = g == 0
        self.assertTrue(np.all(np.abs(serial.e[zero] - linear_e_at_zero_load(gamma[zero]))
                               <= serial.empirical_bound[zero] + 4e-16))
        results = [None] * 4
        errors = []

        def work(k):
            try:
                results[k] = viscor.evaluate("linear", gamma, g, 1e-8, threads=2)
            except Exception as error:  # reported below
                errors.append(error)

        threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(errors, [])
        for r in results:
            for a, b in zip(r, serial):
                self.assertTrue(np.array_equal(a, b))

    def test_concurrent_laws_and_cor(self):
        # Different laws and 50-digit cor calls at once: precision is per thread.
        gamma = np.linspace(0.001, 0.1, 200)
        expected = {law: viscor.evaluate(law, gamma, 0.5, 1e-6, threads=1)
                    for law in ("tsuji", "hunt_crossley")}
        cor_expected = viscor.cor("kuwabara_kono", "0.05", "1", digits=50).e
        out, errors = {}, []

        def evaluate(law):
            try:
                out[law] = viscor.evaluate(law, gamma, 0.5, 1e-6)
            except Exception as error:
                errors.append(error)

        def cor():
            try:
                out["cor"] = viscor.cor("kuwabara_kono", "0.05", "1", digits=50).e
            except Exception as error:
                errors.append(error)

        threads = [threading.Thread(target=evaluate, args=(law,)) for law in expected] + \
                  [threading.Thread(target=cor)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(errors, [])
        for law in expected:
            self.assertTrue(np.array_equal(out[law].e, expected[law].e))
        self.assertEqual(out["cor"], cor_expected)


if __name__ == "__main__":
    unittest.main()
