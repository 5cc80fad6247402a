"""viscor.dask on a LocalCluster of two worker processes: a table merged from its
shards equals the one-process table byte for byte, finished shards are kept and
not computed again, and point batches and evaluate give the one-process results."""

import os
import tempfile
import unittest

import viscor
from viscor_test_support import numpy as np, skip_or_fail

try:
    import distributed
    import viscor.dask
except ImportError:  # python3-distributed missing
    distributed = None

SPEC = {"laws": ["linear", "tsuji"], "gamma": [0, 0.05, {"from": 0.1, "to": 0.3, "count": 3}], "g": [0, 0.5],
        "digits": 20}


def without_timings(r):
    d = r.to_dict()
    d.pop("seconds", None)
    return d


class OnTwoWorkers(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = None
        if distributed is None:
            return
        cls.cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                               dashboard_address=None)
        cls.client = distributed.Client(cls.cluster)

    @classmethod
    def tearDownClass(cls):
        if cls.client is not None:
            cls.client.close()
            cls.cluster.close()

    def setUp(self):
        if distributed is None:
            skip_or_fail(self, "python3-distributed (dask.distributed)")
        if np is None:
            skip_or_fail(self, "numpy")

    def test_table_equals_one_process_and_keeps_finished_shards(self):
        with tempfile.TemporaryDirectory() as tmp:
            one = os.path.join(tmp, "one.csv")
            viscor.table(SPEC, one, threads=1)
            spread = os.path.join(tmp, "spread.csv")
            # Shard 1 of 3 is already done (an earlier, interrupted call): only 0 and 2 are computed.
            os.makedirs(spread + ".shards")
            viscor.table(SPEC, os.path.join(spread + ".shards", "shard-1-of-3.csv"), shard=(1, 3), threads=1)
            with distributed.get_task_stream(self.client) as stream:
                viscor.dask.table(SPEC, spread, self.client, shards=3)
            computed = [t for t in stream.data if t["key"].startswith("_shard_task")]
            self.assertEqual(len(computed), 2, [t["key"] for t in computed])
            with open(one, "rb") as a, open(spread, "rb") as b:
                self.assertEqual(a.read(), b.read())
            self.assertFalse(os.path.exists(spread + ".shards"))

    def test_points_and_evaluate_equal_one_process(self):
        points = [{"law": "tsuji", "gamma": str(0.01 * k), "g": "0.5"} for k in range(10)] + \
                 [{"law": "linear", "gamma": "-1"}]
        mine = viscor.dask.cor_points(points, self.client, chunk=3, digits=20)
        ref = viscor.cor_points(points, digits=20)
        self.assertEqual([without_timings(r) for r in mine], [without_timings(r) for r in ref])
        gamma = np.linspace(1e-3, 0.2, 500)
        spread = viscor.dask.evaluate(self.client, "tsuji", gamma, 0.7, tol=1e-8, chunk=128)
        local = viscor.evaluate("tsuji", gamma, 0.7, tol=1e-8)
        for field in ("e", "one_minus_e", "empirical_bound", "method", "outcome"):
            self.assertTrue(np.array_equal(getattr(spread, field), getattr(local, field)), field)


if __name__ == "__main__":
    unittest.main()
