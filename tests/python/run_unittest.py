"""Runs one test module for ctest: exit 0 when every test passed, 77 when all that ran
passed but some were skipped (ctest's SKIP_RETURN_CODE: reported as skipped, never as
passed), 1 on any failure or error (an import error included).
Usage: python3 run_unittest.py MODULE"""

import sys
import unittest

if __name__ == "__main__":
    suite = unittest.defaultTestLoader.loadTestsFromName(sys.argv[1])
    result = unittest.TextTestRunner(verbosity=2).run(suite)
    if not result.wasSuccessful():
        sys.exit(1)
    sys.exit(77 if result.skipped else 0)
