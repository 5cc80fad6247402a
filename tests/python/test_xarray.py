"""Table.to_xarray() and the NetCDF form of tables (viscor table --format netcdf,
viscor table netcdf): every value against the CSV's own decimals read here, the
enclosures still enclosing, the provenance equal to the sidecar's, and the NetCDF
file read back by xarray equal to to_xarray()."""

import decimal
import fractions
import hashlib
import json
import math
import os
import subprocess
import tempfile
import unittest

import viscor
from viscor_test_support import CLI, REFERENCE_DATA, numpy, optional_module, skip_or_fail

xarray = optional_module("xarray", "python3-xarray")
netCDF4 = optional_module("netCDF4", "python3-netcdf4")

# Two laws x two g x three gamma, proven: every variable the dataset can have, a stick
# (hunt_crossley at g = 2, gamma = 0.5) and the exact gamma = 0 rows.
SPEC = {"laws": ["tsuji", "hunt_crossley"], "gamma": [0, 0.05, 0.5], "g": [0, 2], "digits": 20, "method": "proven"}


def exact(text):
    return fractions.Fraction(decimal.Decimal(text))


class ToXarray(unittest.TestCase):
    def setUp(self):
        if xarray is None:
            skip_or_fail(self, "xarray (python3-xarray)")
        self.tmp = tempfile.TemporaryDirectory()
        self.out = os.path.join(self.tmp.name, "grid.csv")
        self.table = viscor.table(SPEC, self.out, threads=2, format="netcdf")

    def tearDown(self):
        self.tmp.cleanup()

    def test_every_row_is_at_its_grid_point(self):
        ds = self.table.to_xarray()
        self.assertEqual(dict(ds.sizes), {"law": 2, "g": 2, "gamma": 3})
        self.assertEqual(list(ds["law"].values), ["tsuji", "hunt_crossley"])
        self.assertEqual(list(ds["g_exact"].values), ["0", "2"])
        t = self.table
        seen = 0
        for k in range(t.rows):
            at = dict(law=t.strings("law")[k], g=float(t.strings("g")[k]), gamma=float(t.strings("gamma")[k]))
            cell = ds.sel(**at)
            for name in ("e", "one_minus_e", "contact_time", "max_compression"):
                text = t.strings(name)[k]
                self.assertEqual(str(cell[name + "_exact"].values), text)
                value = float(cell[name].values)
                self.assertTrue(math.isnan(value) if text == "" else value == float(text), (name, at, text))
            self.assertEqual(str(cell["outcome"].values), t.strings("outcome")[k])
            self.assertEqual(int(cell["certified_digits"].values), int(t.strings("digits")[k]))
            self.assertEqual(int(cell["proven_digits"].values), int(t.strings("proven_digits")[k]))
            self.assertEqual(str(cell["outcome_proven"].values), t.strings("outcome_proven")[k])
            seen += 1
        self.assertEqual(seen, 12)
        self.assertIn("stick", list(ds["outcome"].values.ravel()))

    def test_the_enclosures_still_enclose(self):
        ds = self.table.to_xarray()
        judged = 0
        for name in ("e", "one_minus_e"):
            for lower, upper, lower_text, upper_text in zip(ds[name + "_lower"].values.ravel(),
                                                            ds[name + "_upper"].values.ravel(),
                                                            ds[name + "_lower_exact"].values.ravel(),
                                                            ds[name + "_upper_exact"].values.ravel()):
                # Fraction(float) is the double's exact value
                self.assertLessEqual(fractions.Fraction(float(lower)), exact(lower_text))
                self.assertGreaterEqual(fractions.Fraction(float(upper)), exact(upper_text))
                # and the tightest such doubles: one step inwards is no bound
                self.assertGreater(fractions.Fraction(math.nextafter(float(lower), math.inf)), exact(lower_text))
                self.assertLess(fractions.Fraction(math.nextafter(float(upper), -math.inf)), exact(upper_text))
                judged += 1
        self.assertEqual(judged, 24)

    def test_provenance_is_the_sidecars(self):
        ds = self.table.to_xarray()
        sidecar = self.table.sidecar
        with open(self.out, "rb") as f:
            self.assertEqual(ds.attrs["table_sha256"], hashlib.sha256(f.read()).hexdigest())
        with open(self.out + ".json", "rb") as f:
            text = f.read()
        self.assertEqual(ds.attrs["sidecar_sha256"], hashlib.sha256(text).hexdigest())
        self.assertEqual(json.loads(ds.attrs["sidecar"]), sidecar)
        self.assertEqual(json.loads(ds.attrs["spec"]), sidecar["spec"])
        for key in ("viscor_version", "git_commit", "date"):
            self.assertEqual(ds.attrs[key], sidecar[key])
        self.assertEqual(ds.attrs["method"], "proven")
        self.assertEqual(ds.attrs["working_digits"], sidecar["scalar"]["decimal_digits"])
        self.assertEqual(ds.attrs["rows"], 12)

    def test_the_netcdf_file_reads_back_unchanged(self):
        if netCDF4 is None:
            return skip_or_fail(self, "netCDF4 (python3-netcdf4)")
        mine = self.table.to_xarray()
        with xarray.open_dataset(os.path.join(self.tmp.name, "grid.nc")) as back:
            back.load()
        self.assertTrue(back.identical(mine))
        # identical() by hand as well: every variable and every attribute
        self.assertEqual(set(back.variables), set(mine.variables))
        for name in mine.variables:
            a, b = mine[name].values, back[name].values
            self.assertEqual(a.shape, b.shape, name)
            if a.dtype.kind == "f":
                self.assertTrue(numpy.array_equal(a, b, equal_nan=True), name)
            else:
                self.assertEqual(a.tolist(), b.tolist(), name)
            self.assertEqual(mine[name].attrs, back[name].attrs, name)
        self.assertEqual(mine.attrs, back.attrs)


@unittest.skipUnless(CLI, "VISCOR_CLI not set")
class NetcdfFromTheCli(unittest.TestCase):
    def setUp(self):
        if xarray is None or netCDF4 is None:
            skip_or_fail(self, "xarray and netCDF4 (python3-xarray, python3-netcdf4)")

    def test_table_format_netcdf(self):
        spec = dict(SPEC, method="certify")
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "spec.json"), "w") as f:
                json.dump(spec, f)
            subprocess.run([CLI, "table", "spec.json", "-o", "cli.csv", "--format", "netcdf", "--quiet"], cwd=tmp,
                           check=True)
            with xarray.open_dataset(os.path.join(tmp, "cli.nc")) as back:
                back.load()
            self.assertTrue(back.identical(viscor.Table(os.path.join(tmp, "cli.csv")).to_xarray()))
            self.assertNotIn("e_lower", back.variables)  # a certified table has no enclosures

    def test_the_netcdf_form_of_a_committed_table(self):
        table = os.path.join(REFERENCE_DATA, "proven", "cor_g_sweep.csv")
        with tempfile.TemporaryDirectory() as tmp:
            nc = os.path.join(tmp, "sweep.nc")
            subprocess.run([CLI, "table", "netcdf", table, "-o", nc], check=True)
            with xarray.open_dataset(nc) as back:
                back.load()
            self.assertTrue(back.identical(viscor.Table(table).to_xarray()))
            self.assertEqual(dict(back.sizes), {"law": 5, "g": 49, "gamma": 3})

    def test_refusals(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "spec.json"), "w") as f:
                json.dump(dict(SPEC, method="certify"), f)
            bad = subprocess.run([CLI, "table", "spec.json", "-o", "t.csv", "--format", "hdf5"], cwd=tmp,
                                 capture_output=True, text=True)
            self.assertEqual(bad.returncode, 2)
            self.assertIn("hdf5", bad.stderr)
            shard = subprocess.run([CLI, "table", "spec.json", "-o", "t.csv", "--format", "netcdf", "--shard", "0/2"],
                                   cwd=tmp, capture_output=True, text=True)
            self.assertEqual(shard.returncode, 2)
            self.assertIn("shard", shard.stderr)
            self.assertEqual(sorted(os.listdir(tmp)), ["spec.json"])  # nothing written
            subprocess.run([CLI, "table", "spec.json", "-o", "s.csv", "--shard", "0/2", "--quiet"], cwd=tmp, check=True)
            part = subprocess.run([CLI, "table", "netcdf", "s.csv"], cwd=tmp, capture_output=True, text=True)
            self.assertNotEqual(part.returncode, 0)
            self.assertIn("merge the shards first", part.stderr)
            self.assertFalse(os.path.exists(os.path.join(tmp, "s.nc")))


if __name__ == "__main__":
    unittest.main()


class PhysicalSpecDataset(unittest.TestCase):
    """A table from a spec in SI: the dataset spans the spec's own axes, in table order."""

    SPEC = {"laws": ["kuwabara_kono"],
            "beads": [{"name": "steel", "youngs_modulus": "2.1e11", "poisson_ratio": "0.3", "radius": "0.002",
                       "density": 7850},
                      {"name": "glass", "youngs_modulus": "6.3e10", "poisson_ratio": "0.23", "radius": "0.002",
                       "m": "8.4e-5"}],
            "walls": ["rigid", {"name": "granite", "youngs_modulus": "5e10", "poisson_ratio": "0.25"}],
            "v0": ["0.05", "1"], "gravity": [0, "9.81"], "target_e": ["0.5", "0.8"], "digits": 20}

    def test_axes_values_and_round_trip(self):
        if xarray is None or netCDF4 is None:
            skip_or_fail(self, "xarray and netCDF4 (python3-xarray, python3-netcdf4)")
        with tempfile.TemporaryDirectory() as tmp:
            t = viscor.table(self.SPEC, os.path.join(tmp, "si.csv"), threads=2, format="netcdf")
            ds = t.to_xarray()
            self.assertEqual(dict(ds.sizes), {"law": 1, "bead": 2, "wall": 2, "gravity": 2, "force": 1,
                                              "target_e": 2, "v0": 2})
            self.assertEqual(list(ds.bead.values), ["steel", "glass"])
            self.assertEqual(list(ds.wall.values), ["rigid", "granite"])
            self.assertEqual(list(ds.density_exact.values), ["7850", ""])
            self.assertTrue(math.isnan(ds.density.values[1]))
            self.assertEqual(list(ds.v0.values), [0.05, 1.0])
            self.assertEqual(ds.v0.attrs["units"], "m s-1")
            self.assertEqual(ds.attrs["contact"], "wall")
            # the grid in table order: the flattened arrays are the CSV's columns
            for name in ("e", "one_minus_e", "gamma", "g", "gamma0", "contact_time_s", "max_compression_m"):
                self.assertEqual(list(ds[name + "_exact"].values.ravel()), t.strings(name), name)
                self.assertEqual(list(ds[name].values.ravel()), [float(x) for x in t.strings(name)], name)
            self.assertEqual(list(ds.outcome.values.ravel()), t.strings("outcome"))
            # e is the target it was calibrated to, at every bead, wall, load and speed
            for target in ("0.5", "0.8"):
                e = ds.e.sel(target_e=float(target)).values
                self.assertLess(abs(e - float(target)).max(), 1e-12)
            with xarray.open_dataset(os.path.join(tmp, "si.nc")) as back:
                self.assertTrue(back.identical(ds))
