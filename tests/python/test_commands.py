"""The in-process subcommands (exact, approx, calibrate, scale, table, scene, dem,
surrogate) against independent values: closed forms written here, eq. (2) written
here, the committed certified tables, and the CLI binary's output for the same
command (another front end, the same files)."""

import decimal
import fractions
import json
import math
import os
import subprocess
import tempfile
import unittest

import viscor
from viscor._inputs import spec_json
from viscor_test_support import (CLI, REFERENCE_DATA, SOURCE_DIR, linear_law_e, mpmath, numpy as np, optional_module,
                                 reference_rows, skip_or_fail)

tqdm = optional_module("tqdm", "python3-tqdm")


def cli_json(*args):
    return json.loads(subprocess.run([CLI, *args, "--json"], check=True, capture_output=True, text=True).stdout)


class Exact(unittest.TestCase):
    @unittest.skipIf(mpmath is None, "needs mpmath")
    def test_linear_law(self):
        r = viscor.exact("linear", "0.2", "0.1", digits=40)
        self.assertTrue(r.exists)
        e, t = linear_law_e("0.2", "0.1")
        self.assertLess(abs(r.decimal("e") - decimal.Decimal(mpmath.nstr(e, 50))), decimal.Decimal("1e-36"))
        self.assertLess(abs(r.decimal("contact_time") - decimal.Decimal(mpmath.nstr(t, 50))), decimal.Decimal("1e-35"))

    def test_none_known(self):
        r = viscor.exact("kuwabara_kono", "0.1", "1")
        self.assertFalse(r.exists)


@unittest.skipUnless(CLI, "VISCOR_CLI not set")
class SameAsTheCli(unittest.TestCase):
    def test_approx(self):
        r = viscor.approx("kuwabara_kono", "0.01", "0.5")
        cli = cli_json("approx", "--model", "kuwabara_kono", "--gamma", "0.01", "--g", "0.5")
        self.assertEqual(r.to_dict(), cli)

    def dem_as_the_cli(self, code, **options):
        """viscor.dem's fields, checked equal to `viscor dem CODE --OPTION VALUE ... --json`'s (timings aside)."""
        cli = cli_json("dem", code, *[w for k, v in options.items() for w in ("--" + k.replace("_", "-"), v)])
        cli.pop("seconds", None)
        mine = viscor.dem(code, **options).to_dict()
        mine.pop("seconds", None)
        self.assertEqual(mine, cli)
        return mine

    def test_dem(self):
        self.dem_as_the_cli("lammps", damping="tsuji", youngs_modulus="3e9", poisson_ratio="0.35", radius="1e-3",
                            density="1200", target_e="0.5", v0="0.01", gravity="9.81")

    def test_dem_by_surrogate(self):
        # The C export's entries (docs/dem.md): the same method in Python and on the command line.
        mine = self.dem_as_the_cli("liggghts", damping="hertz", youngs_modulus="3e9", poisson_ratio="0.35",
                                   radius="1e-3", density="1200", target_e="0.5", v0="0.01", gravity="9.81",
                                   method="surrogate")
        self.assertEqual(mine["method"], "surrogate")
        self.assertIn("error_bound", mine)

    def test_dem_at_a_time_step(self):
        # Entries for the e the code's own update gives at T/50 (docs/dem.md): the CLI's, and at that step.
        mine = self.dem_as_the_cli("lammps", damping="tsuji", youngs_modulus="3e9", poisson_ratio="0.35",
                                   radius="1e-3", density="1200", target_e="0.5", v0="0.01", gravity="9.81",
                                   timestep="T/50")
        self.assertEqual(mine["timestep"], "T/50")
        self.assertNotEqual(mine["deck"]["damping"], mine["continuous_deck_damping"])


def without_timings(value):
    """A JSON value with every "seconds" field (a timing, at any depth) removed."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def same_fields(test, mine, cli):
    """The Python result equals the CLI's JSON object, timings aside."""
    test.assertEqual(without_timings(mine.to_dict()), without_timings(cli))


def cli_words(options):
    return [w for k, v in options.items() for w in ("--" + k.replace("_", "-"), v)]


@unittest.skipUnless(CLI, "VISCOR_CLI not set")
class JobsSameAsTheCli(unittest.TestCase):
    """Each Python function calls the library's job; the CLI calls the same job from
    its own options: the two front ends must agree field for field."""

    BEAD = dict(m="2.05e-3", k="6.9716e9", v0="0.246", gravity="9.8")

    def test_exact(self):
        same_fields(self, viscor.exact("tsuji", "0.1", "0", digits=30),
                    cli_json("exact", "--model", "tsuji", "--gamma", "0.1", "--g", "0", "--digits", "30"))

    def test_scale_both_directions(self):
        same_fields(self, viscor.scale("kuwabara_kono", gamma0="8.49e-7", digits=20, **self.BEAD),
                    cli_json("scale", "--model", "kuwabara_kono", "--gamma0", "8.49e-7", "--digits", "20",
                             *cli_words(self.BEAD)))
        same_fields(self, viscor.scale("kuwabara_kono", gamma="0.1", g="0.5", **self.BEAD),
                    cli_json("scale", "--model", "kuwabara_kono", "--gamma", "0.1", "--g", "0.5",
                             *cli_words(self.BEAD)))

    def test_calibrate_physical_and_by_surrogate(self):
        same_fields(self, viscor.calibrate("kuwabara_kono", "0.893", digits=20, **self.BEAD),
                    cli_json("calibrate", "--model", "kuwabara_kono", "--target-e", "0.893", "--digits", "20",
                             *cli_words(self.BEAD)))
        same_fields(self, viscor.calibrate("tsuji", "0.8", g="0.5", method="surrogate"),
                    cli_json("calibrate", "--model", "tsuji", "--target-e", "0.8", "--g", "0.5", "--method",
                             "surrogate"))

    def test_cor_physical_inputs_and_material(self):
        same_fields(self, viscor.cor("kuwabara_kono", gamma0="8.49e-7", digits=30, **self.BEAD),
                    cli_json("cor", "--model", "kuwabara_kono", "--gamma0", "8.49e-7", "--digits", "30",
                             *cli_words(self.BEAD)))
        glass = dict(youngs_modulus="70e9", poisson_ratio="0.22", radius="1e-3", density="2500", v0="0.5",
                     gamma0="1", gravity="9.81")
        same_fields(self, viscor.cor("tsuji", digits=20, certify=True, **glass),
                    cli_json("cor", "--model", "tsuji", "--digits", "20", "--certify", *cli_words(glass)))

    def test_dem_reverse(self):
        options = dict(damping="tsuji", youngs_modulus="70e9", poisson_ratio="0.22", radius="1e-3", density="2500",
                       deck_damping="0.5", v0="0.5", gravity="9.81")
        r = viscor.dem("lammps", speeds=["0.1", "1"], **options)
        same_fields(self, r, cli_json("dem", "lammps", "--speeds", "0.1,1", *cli_words(options)))

    def test_dem_variables_block_same_as_the_cli(self):
        options = dict(damping="hertz", youngs_modulus="3e9", poisson_ratio="0.35", radius="1e-3", density="1200",
                       target_e="0.5", v0="0.01", gravity="9.81")
        with tempfile.TemporaryDirectory() as scratch:
            mine, theirs = os.path.join(scratch, "python.in"), os.path.join(scratch, "cli.in")
            r = viscor.dem("liggghts", variables=mine, **options)
            cli = cli_json("dem", "liggghts", "--variables", theirs, *cli_words(options))
            self.assertEqual(r.variables, mine)
            self.assertEqual(cli["variables"], theirs)
            with open(mine) as a, open(theirs) as b:
                block = a.read()
                self.assertEqual(block, b.read())
            self.assertIn("variable viscor_damping string " + r.deck.damping_exact + "\n", block)


class PhysicalInputs(unittest.TestCase):
    BEAD = dict(m="2.05e-3", k="6.9716e9", v0="0.246", gravity="9.8")

    def test_cor_equals_scaled_cor_at_the_scaled_point(self):
        # The physical mode is the scaled solve at (gamma, g) of eq. (2): scale() and
        # cor() at that point give the same e (an independent path through the scaling).
        s = viscor.scale("kuwabara_kono", gamma0="8.49e-7", digits=30, **self.BEAD)
        direct = viscor.cor("kuwabara_kono", s.gamma_exact, s.g_exact, digits=30)
        physical = viscor.cor("kuwabara_kono", gamma0="8.49e-7", digits=30, **self.BEAD)
        self.assertEqual(physical.e_exact, direct.e_exact)

    def test_gravity_never_defaults(self):
        with self.assertRaisesRegex(ValueError, "gravity"):
            viscor.cor("kuwabara_kono", m="2.05e-3", k="6.9716e9", v0="0.246", gamma0="8.49e-7")
        with self.assertRaisesRegex(ValueError, "not both"):
            viscor.cor("kuwabara_kono", "0.1", gamma0="8.49e-7", **self.BEAD)
        with self.assertRaisesRegex(TypeError, "mass"):
            viscor.cor("kuwabara_kono", "0.1", mass=1)

    @unittest.skipIf(np is None, "needs numpy")
    def test_evaluate_broadcasts_physical_arrays(self):
        v0 = np.array([0.05, 0.246, 1.0])
        r = viscor.evaluate("kuwabara_kono", m=2.05e-3, k=6.9716e9, v0=v0[:, None], gamma0=8.49e-7,
                            gravity=np.array([0.0, 9.8]), tol=1e-9)
        self.assertEqual(r.e.shape, (3, 2))
        for i, speed in enumerate(v0):
            for j, grav in enumerate((0.0, 9.8)):
                ref = viscor.cor("kuwabara_kono", m="2.05e-3", k="6.9716e9", v0=float(speed), gamma0="8.49e-7",
                                 gravity=grav, digits=30)
                self.assertLessEqual(abs(r.e[i, j] - float(ref.e)), 1e-9 + 1e-15, (speed, grav))
        with self.assertRaisesRegex(ValueError, "gravity"):
            viscor.evaluate("kuwabara_kono", m=2.05e-3, k=6.9716e9, v0=v0, gamma0=8.49e-7)


class Scale(unittest.TestCase):
    @unittest.skipIf(mpmath is None, "needs mpmath")
    def test_equation_2(self):
        m, k, v0, gamma0, gravity = "0.154", "3.6138e10", "1", "1.5237e-6", "9.8"
        r = viscor.scale("kuwabara_kono", m=m, k=k, v0=v0, gamma0=gamma0, gravity=gravity, digits=30)
        self.assertEqual(r.direction, "physical_to_scaled")
        with mpmath.workdps(40):
            M, K, V, G0, GR = map(mpmath.mpf, (m, k, v0, gamma0, gravity))
            a, b = mpmath.mpf(3) / 2, mpmath.mpf(3) / 2
            gamma = G0 * V ** (2 * b / (a + 1) - 1) * (K / M) ** (1 - b / (a + 1))
            g = (M / K) ** (1 / (a + 1)) * V ** (-2 * a / (a + 1)) * GR
            T = (M / K) ** (1 / (a + 1)) * V ** ((1 - a) / (a + 1))
            for field, value in (("gamma", gamma), ("g", g), ("time_scale_s", T)):
                mine = r.decimal(field)
                ref = decimal.Decimal(mpmath.nstr(value, 35))
                self.assertLess(abs(mine - ref) / ref, decimal.Decimal("1e-27"), field)
        back = viscor.scale("kuwabara_kono", m=m, k=k, v0=v0, gravity=gravity, gamma=r.gamma_exact, g=r.g_exact,
                            digits=30)
        self.assertLess(abs(back.decimal("gamma0") - decimal.Decimal(gamma0)) / decimal.Decimal(gamma0),
                        decimal.Decimal("1e-27"))


class Calibrate(unittest.TestCase):
    def test_linear_law_at_zero_load(self):
        # e = exp(-gamma pi / (2 w)): gamma = 2 L / sqrt(pi^2 + L^2) with L = -ln e.
        r = viscor.calibrate("linear", "0.9", g="0", digits=20)
        L = -math.log(0.9)
        exact_gamma = 2 * L / math.sqrt(math.pi**2 + L**2)
        self.assertAlmostEqual(float(r.gamma), exact_gamma, delta=1e-12)
        self.assertLessEqual(abs(float(r.e) - 0.9), float(r.target_bound) + 1e-15)


class Table(unittest.TestCase):
    def test_spec_to_csv(self):
        with tempfile.TemporaryDirectory() as tmp:
            spec = os.path.join(tmp, "spec.json")
            with open(spec, "w") as f:
                json.dump({"laws": ["linear", "kuwabara_kono"], "gamma": ["0.0137", "0.05"], "g": ["0", "1"],
                           "digits": 36, "min_digits": 30}, f)
            out = os.path.join(tmp, "t.csv")
            self.assertEqual(viscor.table(spec, out, threads=1), out)
            rows, sidecar = viscor.read_table(out)
            self.assertEqual(len(rows), 8)
            self.assertEqual(sidecar["rows_total"], 8)
            committed = {(r["law"], r["gamma"], r["g"]): r for r in reference_rows()}
            for row in rows:
                ref = committed.get((row["law"], row["gamma"], row["g"]))
                if ref is None:
                    continue
                digits = min(int(row["digits"]), int(ref["digits"]))
                diff = abs(decimal.Decimal(row["e"]) - decimal.Decimal(ref["e"]))
                self.assertLessEqual(diff, decimal.Decimal(10) ** (1 - digits), row)

    def test_no_partial_output_on_error(self):
        with tempfile.TemporaryDirectory() as tmp:
            spec = os.path.join(tmp, "spec.json")
            with open(spec, "w") as f:
                f.write('{"laws": ["linear"], "gamma": ["-1"], "g": ["0"]}')
            with self.assertRaises(ValueError):
                viscor.table(spec, os.path.join(tmp, "t.csv"))
            self.assertFalse(os.path.exists(os.path.join(tmp, "t.csv")))


@unittest.skipUnless(CLI, "VISCOR_CLI not set")
class PhysicalTable(unittest.TestCase):
    """A spec in SI: each row is viscor.cor of the row's physical inputs."""

    SPEC = {"laws": ["kuwabara_kono"],
            "beads": [{"name": "steel", "youngs_modulus": "2.1e11", "poisson_ratio": "0.3", "radius": "0.004",
                       "density": 7850},
                      {"name": "glass", "youngs_modulus": "6.3e10", "poisson_ratio": "0.23", "radius": "0.004",
                       "density": 2500}],
            "v0": ["0.05", "1"], "gravity": [0, "9.81"], "gamma0": "8.49e-7", "digits": 20}

    def test_rows_are_viscor_cor_of_their_inputs(self):
        with tempfile.TemporaryDirectory() as tmp:
            t = viscor.table(self.SPEC, os.path.join(tmp, "si.csv"), threads=2)
            self.assertEqual(t.rows, 8)
            self.assertEqual(t.column("bead"), ["steel"] * 4 + ["glass"] * 4)
            self.assertEqual(t.column("wall"), ["rigid"] * 8)
            self.assertEqual(list(t.column("v0")), [0.05, 1.0] * 4)
            self.assertEqual(list(t.column("gravity")), [0.0, 0.0, 9.81, 9.81] * 2)
            self.assertEqual(t.sidecar["spec"]["gravity"], [{"value": "0"}, {"value": "9.81"}])
            for i in range(t.rows):
                inputs = {name: t.strings(name)[i] for name in
                          ("youngs_modulus", "poisson_ratio", "radius", "density", "v0", "gamma0", "gravity", "force")}
                r = viscor.cor("kuwabara_kono", digits=20, certify=True, **inputs)
                self.assertEqual(t.strings("gamma")[i], r.gamma_exact, i)
                self.assertEqual(t.strings("g")[i], r.g_exact, i)
                self.assertEqual(t.strings("e")[i], r.certified.e_exact, i)
                self.assertEqual(t.strings("one_minus_e")[i], r.certified.one_minus_e_exact, i)
                self.assertEqual(int(t.strings("digits")[i]), r.certified.certified_digits, i)
            with self.assertRaisesRegex(viscor.ParseError, r"field gravity: missing"):
                viscor.table({k: v for k, v in self.SPEC.items() if k != "gravity"}, os.path.join(tmp, "x.csv"))


class TableJobSameAsTheCli(unittest.TestCase):
    """viscor.table calls the library's table job: the same bytes as `viscor table`."""

    SPEC = {"laws": ["linear", "tsuji"], "gamma": [0, 0.05, {"from": 0.1, "to": 0.3, "count": 3}], "g": [0, 0.5],
            "digits": 20}

    def cli_table(self, tmp, spec):
        path = os.path.join(tmp, "spec.json")
        with open(path, "w") as f:
            f.write(spec_json(spec))  # the spec's numbers as viscor.table reads them (floats exactly)
        out = os.path.join(tmp, "cli.csv")
        subprocess.run([CLI, "table", path, "-o", out, "--quiet"], check=True)
        with open(out, "rb") as f:
            return f.read()

    def test_dict_spec_and_columns(self):
        with tempfile.TemporaryDirectory() as tmp:
            t = viscor.table(self.SPEC, os.path.join(tmp, "py.csv"), threads=2)
            self.assertIsInstance(t, str)
            self.assertEqual(t, os.path.join(tmp, "py.csv"))
            with open(t, "rb") as f:
                self.assertEqual(f.read(), self.cli_table(tmp, self.SPEC))
            self.assertEqual(t.rows, 20)
            e = t.column("e")
            self.assertEqual(e.dtype, np.float64)
            self.assertEqual(list(e), [float(x) for x in t.strings("e")])
            self.assertEqual(t.column("law")[:1], ["linear"])
            self.assertEqual(t.sidecar["rows_total"], 20)

    def test_dict_numbers_are_read_as_cor_reads_them(self):
        spec = {"laws": ["tsuji"], "gamma": [decimal.Decimal("0.05"), fractions.Fraction(1, 10), np.float64(0.2), 0.3],
                "g": [np.int64(0)], "digits": 20}
        with tempfile.TemporaryDirectory() as tmp:
            t = viscor.table(spec, os.path.join(tmp, "py.csv"), threads=1)
            # a float is its exact binary value (Decimal(float) is exact), as viscor.cor takes it
            self.assertEqual(list(t.strings("gamma")), ["0.05", "0.1", str(decimal.Decimal(0.2)), str(decimal.Decimal(0.3))])
            with self.assertRaisesRegex(viscor.InvalidParameter, r"spec\.gamma\[0\]"):
                viscor.table(dict(spec, gamma=[float("nan")]), os.path.join(tmp, "nan.csv"))
            with self.assertRaisesRegex(TypeError, r"spec\.gamma\[0\]"):
                viscor.table(dict(spec, gamma=[np.float32(0.5)]), os.path.join(tmp, "f32.csv"))

    def test_interrupted_then_resumed(self):
        import _thread
        import threading
        # About 2.4 s of rows in one thread (certified, no closed form), so the interrupt
        # at 0.5 s lands mid-table on any machine this suite runs on.
        spec = dict(self.SPEC, laws=["tsuji", "hunt_crossley"], digits=50, gamma=[{"from": 0, "to": 1, "count": 21}])
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "py.csv")
            timer = threading.Timer(0.5, _thread.interrupt_main)
            timer.start()
            try:
                with self.assertRaises(KeyboardInterrupt) as caught:
                    viscor.table(spec, out, threads=1)
            finally:
                timer.cancel()
            self.assertIn("resume=True", str(caught.exception))
            self.assertNotIn("--resume", str(caught.exception))  # Python's spelling, not the CLI's
            self.assertTrue(os.path.exists(out + ".partial"))
            self.assertFalse(os.path.exists(out))
            t = viscor.table(spec, out, threads=2, resume=True)
            self.assertGreater(t.sidecar["rows_from_earlier_sessions"], 0)
            with open(out, "rb") as f:
                self.assertEqual(f.read(), self.cli_table(tmp, spec))

    def test_sigterm_keeps_the_finished_rows_and_releases_the_lock(self):
        """A batch scheduler's SIGTERM to a Python process running viscor.table: the
        finished rows stay in OUT.partial, the lock file goes, resume=True finishes the
        same table as the CLI's."""
        import signal
        import sys
        import time
        spec = dict(self.SPEC, laws=["tsuji", "hunt_crossley"], digits=50, gamma=[{"from": 0, "to": 1, "count": 41}])
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "py.csv")
            script = f"import viscor\nviscor.table({spec!r}, {out!r}, threads=1)\n"
            env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
            child = subprocess.Popen([sys.executable, "-c", script], env=env, stderr=subprocess.PIPE, text=True)
            try:
                deadline = time.monotonic() + 60
                while time.monotonic() < deadline and child.poll() is None:  # a row or more finished
                    if os.path.exists(out + ".partial") and os.path.getsize(out + ".partial") > 200:
                        break
                    time.sleep(0.02)
                self.assertIsNone(child.poll(), "the table finished before it could be interrupted")
                self.assertTrue(os.path.exists(out + ".lock"))
                child.send_signal(signal.SIGTERM)
                _, err = child.communicate(timeout=60)
            finally:
                if child.poll() is None:
                    child.kill()
            self.assertNotEqual(child.returncode, 0)
            self.assertIn("KeyboardInterrupt: interrupted: ", err)
            self.assertIn("resume=True", err)
            self.assertTrue(os.path.exists(out + ".partial"))
            self.assertFalse(os.path.exists(out + ".lock"))  # released: the run's own lock file is removed
            self.assertFalse(os.path.exists(out))
            t = viscor.table(spec, out, threads=2, resume=True)
            self.assertGreater(t.sidecar["rows_from_earlier_sessions"], 0)
            self.assertLess(t.sidecar["rows_from_earlier_sessions"], 164)
            with open(out, "rb") as f:
                self.assertEqual(f.read(), self.cli_table(tmp, spec))

    def test_progress_is_reported(self):
        calls = []
        with tempfile.TemporaryDirectory() as tmp:
            viscor.table(self.SPEC, os.path.join(tmp, "py.csv"), threads=1, progress=lambda d, t: calls.append((d, t)))
        self.assertTrue(calls)
        self.assertEqual(calls[-1], (20, 20))
        self.assertEqual([d for d, _ in calls], sorted(d for d, _ in calls))
        with self.assertRaises(TypeError):
            viscor.table(self.SPEC, "never.csv", progress="yes")
        with tempfile.TemporaryDirectory() as tmp:  # a failing display does not stop the run
            t = viscor.table(self.SPEC, os.path.join(tmp, "py.csv"), threads=1, progress=lambda d, t: 1 / 0)
            self.assertEqual(len(t.column("e")), 20)
        from viscor._progress import progress_reporter
        if tqdm is None:
            return skip_or_fail(self, "tqdm (python3-tqdm)")
        import io
        from viscor._progress import _Bar
        self.assertIsInstance(progress_reporter(True, "row", "test"), _Bar)  # drawn only on a terminal
        drawn = io.StringIO()
        bar = _Bar(lambda **kw: tqdm.tqdm(**dict(kw, disable=False, file=drawn)), "row", "test")
        bar(3, 20)
        bar(20, 20)
        bar.close()
        self.assertIn("20/20", drawn.getvalue())


@unittest.skipUnless(CLI, "VISCOR_CLI not set")
class PointsSameAsTheCli(unittest.TestCase):
    def test_points(self):
        points = [{"law": "tsuji", "gamma": "0.1", "g": "0.5"}, {"alpha": "3/2", "beta": "1", "gamma": 0.25},
                  {"law": "linear", "gamma": "-1"}, {"law": "hunt_crossley", "gamma": "0.3", "g": "1", "digits": 30}]
        r = viscor.cor_points(points, digits=20, threads=2)
        text = "".join(json.dumps(p) + "\n" for p in points)
        cli = subprocess.run([CLI, "cor", "--points", "-", "--digits", "20"], input=text, capture_output=True,
                             text=True)
        self.assertEqual(cli.returncode, 2)
        lines = [json.loads(line) for line in cli.stdout.splitlines()]
        self.assertEqual(len(r), len(lines))
        for mine, theirs in zip(r, lines):
            mine, theirs = mine.to_dict(), dict(theirs)
            mine.pop("seconds", None), theirs.pop("seconds", None)
            self.assertEqual(mine, theirs)
        self.assertIn("error", r[2])
        self.assertTrue(math.isnan(r.column("e")[2]))
        self.assertEqual(r.strings("e")[0], lines[0]["e"])


class Scene(unittest.TestCase):
    def test_steel_bead(self):
        path = os.path.join(SOURCE_DIR, "docs", "examples", "steel_bead.json")
        r = viscor.scene(path)
        self.assertGreater(r.impacts, 0)
        for row in r.rows:
            self.assertLessEqual(float(row.empirical_bound), float(r.tolerance))
        self.assertEqual(r.strings("e"), [row.e_exact for row in r.rows])
        if np is not None:
            self.assertTrue(np.array_equal(r.column("e"), np.array([float(row.e) for row in r.rows])))
        with tempfile.TemporaryDirectory() as tmp:
            out = viscor.scene(path, os.path.join(tmp, "steel.csv"))
            self.assertTrue(os.path.getsize(out) > 0)


class Surrogate(unittest.TestCase):
    def test_committed_surrogate(self):
        law = "kuwabara_kono"
        s = viscor.find_surrogate(law)
        if s is None:
            skip_or_fail(self, "no committed surrogate of " + law + " (reference_data/surrogates/)")
        bound = s.error_bound
        rows = [r for r in reference_rows() if r["law"] == law and r["outcome"] == "rebound"][::50]
        checked = 0
        for row in rows:
            v = s(float(row["gamma"]), float(row["g"]))
            if not v["in_domain"] or v["e"] < 1e-2 or "abs_e" not in bound:
                continue
            self.assertLessEqual(abs(v["e"] - float(row["e"])), bound["abs_e"] + 1e-15, row)
            checked += 1
        if np is not None and checked:
            gamma = np.array([float(r["gamma"]) for r in rows])
            g = np.array([float(r["g"]) for r in rows])
            ev = viscor.evaluate(law, gamma, g, max(bound["abs_e"], 1e-12), surrogate=s)
            ref = np.array([float(r["e"]) for r in rows])
            self.assertTrue(np.all(np.abs(ev.e - ref) <= ev.empirical_bound + 1e-15))


if __name__ == "__main__":
    unittest.main()
