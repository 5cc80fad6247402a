"""Bad input raises a Python exception naming the value; nothing crashes the
interpreter. The crashing cases run in a child interpreter, so a crash (a
signal) fails the test instead of killing the test runner."""

import decimal
import fractions
import os
import subprocess
import sys
import unittest

import viscor


class BadInputRaises(unittest.TestCase):
    def check(self, exception, words, call, *args, **kwargs):
        with self.assertRaises(exception) as caught:
            call(*args, **kwargs)
        for w in words:
            self.assertIn(w, str(caught.exception))
        return caught.exception

    def test_hierarchy(self):
        self.assertTrue(issubclass(viscor.InvalidParameter, ValueError))
        self.assertTrue(issubclass(viscor.InvalidParameter, viscor.Error))
        self.assertTrue(issubclass(viscor.PrecisionUnavailable, ValueError))
        self.assertTrue(issubclass(viscor.ParseError, ValueError))
        self.assertTrue(issubclass(viscor.ConvergenceError, RuntimeError))

    def test_nan_and_infinity(self):
        self.check(viscor.InvalidParameter, ["gamma", "nan"], viscor.cor, "tsuji", float("nan"), 0)
        self.check(viscor.InvalidParameter, ["g", "inf"], viscor.cor, "tsuji", "0.1", float("inf"))
        self.check(viscor.InvalidParameter, ["gamma", "NaN"], viscor.cor, "tsuji", decimal.Decimal("NaN"), 0)
        self.check(viscor.InvalidParameter, ["gamma", "'nan'"], viscor.cor, "tsuji", "nan", 0)

    def test_messages_name_python_keywords(self):
        # The library names fields; Python shows them as its keywords, never as the CLI's options.
        e = self.check(viscor.InvalidParameter, ["dem needs youngs_modulus (Pa)"], viscor.dem, "lammps",
                       damping="tsuji", poisson_ratio="0.3", radius="1e-3", density="2500", gravity="9.81",
                       target_e="0.8", v0="0.5")
        self.assertNotIn("--", str(e))
        e = self.check(viscor.InvalidParameter, ["gravity", "never defaults"], viscor.evaluate, "tsuji", m=1e-3,
                       k=1e9, v0=0.5, gamma0=1e-3)
        self.assertNotIn("--", str(e))

    def test_committed_data_is_not_replaced(self):
        # A table whose name a SHA256SUMS beside it lists is committed data: refused before
        # any work, the file and the manifest untouched (the CLI asks with --update-committed).
        import hashlib
        import tempfile
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "cor_report_grid.csv")
            with open(out, "w") as f:
                f.write("law,gamma\n")
            line = hashlib.sha256(b"law,gamma\n").hexdigest() + "  cor_report_grid.csv\n"
            with open(os.path.join(tmp, "SHA256SUMS"), "w") as f:
                f.write(line)
            spec = {"laws": ["linear"], "gamma": [0.05], "g": 0, "digits": 20}
            self.check(viscor.InvalidParameter, ["committed data", "cor_report_grid.csv"], viscor.table, spec, out)
            with open(out) as f:
                self.assertEqual(f.read(), "law,gamma\n")
            with open(os.path.join(tmp, "SHA256SUMS")) as f:
                self.assertEqual(f.read(), line)
            self.assertFalse(os.path.exists(out + ".partial"))

    def test_negative_gamma(self):
        # The message names the value as parsed at the working precision (-1.000...e-01).
        self.check(ValueError, ["gamma", "-1.0"], viscor.cor, "tsuji", "-0.1", "0")
        self.check(ValueError, ["gamma"], viscor.cor, "tsuji", fractions.Fraction(-1, 3), "0")

    def test_bad_law(self):
        self.check(ValueError, ["no_such_law"], viscor.cor, "no_such_law", "0.1", "0")
        self.check(ValueError, ["alpha", "1/2"], viscor.cor, None, "0.1", "0", alpha="0.5", beta="1")  # named as 1/2
        self.check(ValueError, ["beta"], viscor.cor, None, "0.1", "0", alpha="3/2", beta="0.9")
        self.check(ValueError, ["alpha"], viscor.cor, None, "0.1", "0", alpha="x", beta="1")
        self.check(ValueError, ["not both"], viscor.cor, "tsuji", "0.1", "0", alpha="3/2", beta="1")

    def test_digits(self):
        self.check(viscor.PrecisionUnavailable, ["digits = 1000000", "maximum"], viscor.cor, "tsuji", "0.1", 0,
                   digits=10**6)
        self.check(viscor.PrecisionUnavailable, ["digits = 100000000000000000000"], viscor.cor, "tsuji", "0.1", 0,
                   digits=10**20)
        self.check(viscor.PrecisionUnavailable, ["digits = 0"], viscor.cor, "tsuji", "0.1", 0, digits=0)
        self.check(TypeError, ["digits"], viscor.cor, "tsuji", "0.1", 0, digits=50.0)
        self.check(TypeError, ["digits"], viscor.cor, "tsuji", "0.1", 0, digits="50")

    def test_wrong_types(self):
        self.check(TypeError, ["gamma", "list"], viscor.cor, "tsuji", [0.1], 0)
        self.check(TypeError, ["gamma", "bool"], viscor.cor, "tsuji", True, 0)
        self.check(TypeError, ["g", "NoneType"], viscor.cor, "tsuji", "0.1", None)
        self.check(TypeError, ["law"], viscor.cor, 3, "0.1", 0)
        self.check(TypeError, ["gamma"], viscor.cor, "tsuji")
        self.check(TypeError, ["certify"], viscor.cor, "tsuji", "0.1", certify="yes")

    def test_division_by_zero_and_bad_fraction_text(self):
        self.check(ValueError, ["divides by zero"], viscor.cor, "tsuji", "1/0", 0)
        self.check(ValueError, ["gamma"], viscor.cor, "tsuji", "1/2/3", 0)

    def test_commands(self):
        self.check(ValueError, ["gravity"], viscor.scale, "kuwabara_kono", m="2.05e-3", k="6.9716e9",
                   gamma0="8.49e-7", v0="0.246")
        self.check(TypeError, ["no_such_option"], viscor.scale, "linear", no_such_option=1)
        self.check(TypeError, ["no_such_option"], viscor.exact, "linear", "0.1", 0, no_such_option=1)
        self.check(ValueError, ["target"], viscor.calibrate, "tsuji", "1.5", g="0.1")
        # A file that cannot be read is a viscor.Error (as the library classifies it), naming the file.
        self.check(viscor.Error, ["does-not-exist.json"], viscor.table, "does-not-exist.json", "out.csv")


class NothingCrashes(unittest.TestCase):
    """The interpreter survives every bad call (run in a child; exit 0 = survived)."""

    def test_child_interpreter_survives(self):
        script = r"""
import viscor, decimal, fractions
calls = [
    lambda: viscor.cor('tsuji', float('nan'), 0),
    lambda: viscor.cor('tsuji', '-1', 0),
    lambda: viscor.cor('tsuji', '1e999999999', 0),
    lambda: viscor.cor('tsuji', '0.1', 0, digits=10**30),
    lambda: viscor.cor('tsuji', '0.1', 0, digits=-5),
    lambda: viscor.cor(None, '0.1', 0, alpha='1/0', beta='1'),
    lambda: viscor.cor(None, '0.1', 0, alpha='0.99', beta='1'),
    lambda: viscor.cor('tsuji', object(), 0),
    lambda: viscor.cor('tsuji', '0.1', 0, max_steps=-1),
    lambda: viscor.cor('tsuji', '0.1', 0, tolerance='abc'),
    lambda: viscor.exact('tsuji', 'x'),
    lambda: viscor.run_cli('no-such-command'),
    lambda: viscor.run_cli('cor', '--gamma', ''),
    lambda: viscor.Surrogate('/nonexistent/file.surrogate'),
]
for call in calls:
    try:
        call()
    except (ValueError, TypeError, viscor.Error) as error:
        pass
    else:
        raise SystemExit('no exception from a bad call')
print('survived')
"""
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ,
                              timeout=120)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("survived", done.stdout)


if __name__ == "__main__":
    unittest.main()
