"""examples/python/cor_vs_gamma.py runs and writes its figure (to a temporary directory)."""

import os
import subprocess
import sys
import tempfile
import unittest

from viscor_test_support import SOURCE_DIR, numpy, optional_module

matplotlib = optional_module("matplotlib", "python3-matplotlib")


@unittest.skipIf(numpy is None or matplotlib is None, "needs NumPy and matplotlib")
class Example(unittest.TestCase):
    def test_cor_vs_gamma(self):
        script = os.path.join(SOURCE_DIR, "examples", "python", "cor_vs_gamma.py")
        with tempfile.TemporaryDirectory() as tmp:
            done = subprocess.run([sys.executable, script, "--out", tmp, "--points", "25", "--repository",
                                   SOURCE_DIR], capture_output=True, text=True, timeout=600)
            self.assertEqual(done.returncode, 0, done.stderr)
            figure = os.path.join(tmp, "cor_kuwabara_kono.png")
            self.assertTrue(os.path.exists(figure))
            with open(figure, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
            self.assertIn("certified rows checked", done.stdout)


if __name__ == "__main__":
    unittest.main()
