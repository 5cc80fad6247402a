"""viscor.export_surrogates: the same files as the command-line tool's
`viscor surrogate export --language c`, and for all laws the committed export."""

import hashlib
import os
import subprocess
import tempfile
import unittest

import viscor
from viscor_test_support import CLI, SOURCE_DIR


def read(path):
    with open(path, "rb") as f:
        return f.read()


class SurrogateExport(unittest.TestCase):
    def test_one_law_matches_the_cli(self):
        with tempfile.TemporaryDirectory() as d:
            paths = viscor.export_surrogates(os.path.join(d, "py"), law="tsuji")
            self.assertEqual([os.path.basename(p) for p in paths], ["viscor_surrogate_tsuji.h", "viscor_surrogate_tsuji.c"])
            subprocess.run([CLI, "surrogate", "export", "--language", "c", "-o", os.path.join(d, "cli"), "--law", "tsuji",
                            "--quiet"], check=True)
            for p in paths:
                self.assertEqual(read(p), read(os.path.join(d, "cli", os.path.basename(p))))

    def test_all_laws_is_the_committed_export(self):
        with tempfile.TemporaryDirectory() as d:
            for p in viscor.export_surrogates(d):
                self.assertEqual(read(p), read(os.path.join(SOURCE_DIR, "examples", "c_export", os.path.basename(p))))

    def test_refuses_unknown_law_and_language(self):
        with tempfile.TemporaryDirectory() as d:
            with self.assertRaises(viscor.InvalidParameter):
                viscor.export_surrogates(d, law="no_such_law")
            with self.assertRaises(viscor.InvalidParameter):
                viscor.export_surrogates(d, language="fortran")
            with self.assertRaises(TypeError):
                viscor.export_surrogates(d, law=[1])

    def test_refuses_a_changed_surrogate_and_writes_nothing(self):
        committed = os.path.join(SOURCE_DIR, "reference_data", "surrogates")
        with tempfile.TemporaryDirectory() as d:
            surrogates, out = os.path.join(d, "surrogates"), os.path.join(d, "out")
            os.mkdir(surrogates)
            text = read(os.path.join(committed, "tsuji.surrogate"))
            table = read(os.path.join(committed, "tsuji.surrogate.verification.csv"))
            with open(os.path.join(surrogates, "tsuji.surrogate"), "wb") as f:
                f.write(text.replace(b"0.33417913660990911", b"0.33417913660990912", 1))
            with open(os.path.join(surrogates, "tsuji.surrogate.verification.csv"), "wb") as f:
                f.write(table)
            with open(os.path.join(surrogates, "SHA256SUMS"), "w") as f:
                f.write(hashlib.sha256(text).hexdigest() + "  tsuji.surrogate\n")
            with self.assertRaisesRegex(viscor.InvalidParameter, "does not match its SHA-256"):
                viscor.export_surrogates(out, law="tsuji", surrogate_directory=surrogates)
            self.assertFalse(os.path.exists(os.path.join(out, "viscor_surrogate_tsuji.c")))


if __name__ == "__main__":
    unittest.main()
