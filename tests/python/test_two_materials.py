"""A wall of its own material and two beads of different materials from Python:
the same answers as the CLI (another front end, the same library job), and the
reduced mass and stiffness of Hertz theory written out here."""

import json
import math
import subprocess
import unittest

import viscor
from viscor_test_support import CLI

GLASS = dict(youngs_modulus="63e9", poisson_ratio="0.22", radius="1e-3", density="2500")
STEEL_BEAD = dict(contact="pair", other_youngs_modulus="200e9", other_poisson_ratio="0.3", other_radius="1.5e-3",
                  other_density="7800")
STEEL_PLATE = dict(wall_youngs_modulus="200e9", wall_poisson_ratio="0.3")


def words(options):
    return [w for k, v in options.items() for w in ("--" + k.replace("_", "-"), v)]


def cli_json(*args):
    return json.loads(subprocess.run([CLI, *args, "--json"], check=True, capture_output=True, text=True).stdout)


def without_seconds(d):
    return {k: v for k, v in d.items() if k != "seconds"}


class TwoMaterials(unittest.TestCase):
    def test_pair_is_the_relative_motion(self):
        r = viscor.cor("tsuji", digits=30, v0="0.5", gamma0="1e-8", gravity="9.81", **GLASS, **STEEL_BEAD)
        m1, m2 = 4 / 3 * math.pi * 1e-9 * 2500, 4 / 3 * math.pi * 1.5e-3 ** 3 * 7800
        e_star = 1 / ((1 - 0.22 ** 2) / 63e9 + (1 - 0.3 ** 2) / 200e9)
        k = 4 / 3 * e_star * math.sqrt(1e-3 * 1.5e-3 / 2.5e-3)
        direct = viscor.cor("tsuji", digits=30, m=m1 * m2 / (m1 + m2), k=k, v0="0.5", gamma0="1e-8", gravity="0")
        self.assertAlmostEqual(float(r.gamma) / float(direct.gamma), 1, delta=1e-14)
        self.assertEqual(float(r.g), 0)  # gravity drops out of a pair

    def test_contact_must_be_a_word(self):
        with self.assertRaises(TypeError):
            viscor.cor("tsuji", v0="0.5", gamma0="1e-8", gravity="9.81", contact=2, **GLASS)
        with self.assertRaises(viscor.InvalidParameter):
            viscor.cor("tsuji", v0="0.5", gamma0="1e-8", gravity="9.81", other_radius="1e-3", **GLASS)

    def test_evaluate_takes_the_pair(self):
        import numpy as np
        v0 = np.array([0.1, 0.5, 1.0])
        r = viscor.evaluate("tsuji", tol=1e-10, v0=v0, gamma0=1e-8, gravity=9.81, **GLASS, **STEEL_BEAD)
        for i, v in enumerate(v0):
            one = viscor.cor("tsuji", digits=20, v0=repr(float(v)), gamma0="1e-8", gravity="9.81", **GLASS, **STEEL_BEAD)
            self.assertAlmostEqual(float(r.e[i]), float(one.e), delta=1e-10)
        plate = viscor.evaluate("tsuji", tol=1e-10, v0=0.5, gamma0=1e-8, gravity=9.81, **GLASS, **STEEL_PLATE)
        one = viscor.cor("tsuji", digits=20, v0="0.5", gamma0="1e-8", gravity="9.81", **GLASS, **STEEL_PLATE)
        self.assertAlmostEqual(float(plate.e), float(one.e), delta=1e-10)
        with self.assertRaises(viscor.InvalidParameter):
            viscor.evaluate("tsuji", v0=0.5, gamma0=1e-8, gravity=9.81, wall_youngs_modulus=2e11, **GLASS)

    @unittest.skipUnless(CLI, "VISCOR_CLI not set")
    def test_cor_same_as_cli(self):
        r = viscor.cor("tsuji", digits=20, v0="0.5", gamma0="1e-8", gravity="9.81", **GLASS, **STEEL_PLATE)
        cli = cli_json("cor", "--model", "tsuji", "--digits", "20", "--v0", "0.5", "--gamma0", "1e-8", "--gravity",
                       "9.81", *words(GLASS), *words(STEEL_PLATE))
        self.assertEqual(without_seconds(r.to_dict()), without_seconds(cli))

    @unittest.skipUnless(CLI, "VISCOR_CLI not set")
    def test_dem_same_as_cli(self):
        options = dict(damping="tsuji", target_e="0.8", v0="0.5", gravity="9.81", **GLASS, **STEEL_BEAD)
        r = viscor.dem("lammps", **options)
        cli = cli_json("dem", "lammps", *words(options))
        self.assertEqual(without_seconds(r.to_dict()), without_seconds(cli))
        self.assertIn("pair_coeff 1 2 hertz/material " + r.deck.exact("cross_youngs_modulus"), r.snippet)


if __name__ == "__main__":
    unittest.main()
