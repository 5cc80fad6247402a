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

    @staticmethod
    def one_process_and_a_kept_shard(tmp, index, count):
        """The one-process table, and the path of a Dask table whose shards folder
        already holds shard index of count (an earlier, interrupted call)."""
        one = os.path.join(tmp, "one.csv")
        viscor.table(SPEC, one, threads=1)
        spread = os.path.join(tmp, "spread.csv")
        os.makedirs(spread + ".shards")
        viscor.table(SPEC, os.path.join(spread + ".shards", f"shard-{index}-of-{count}.csv"), shard=(index, count),
                     threads=1)
        return one, spread

    def test_table_equals_one_process_and_keeps_finished_shards(self):
        with tempfile.TemporaryDirectory() as tmp:
            # Shard 1 of 3 is already done: only 0 and 2 are computed.
            one, spread = self.one_process_and_a_kept_shard(tmp, 1, 3)
            with distributed.get_task_stream(self.client) as stream:
                viscor.dask.table(SPEC, spread, self.client, shards=3)
            computed = [t for t in stream.data if t["key"].startswith("_shard_task")]
            self.assertEqual(len(computed), 2, [t["key"] for t in computed])
            with open(one, "rb") as a, open(spread, "rb") as b:
                self.assertEqual(a.read(), b.read())
            self.assertFalse(os.path.exists(spread + ".shards"))

    def test_a_rerun_with_another_shard_count_discards_the_old_shards(self):
        with tempfile.TemporaryDirectory() as tmp:
            one, spread = self.one_process_and_a_kept_shard(tmp, 0, 3)
            open(os.path.join(spread + ".shards", "shard-1-of-2.csv.tmp.999999"), "w").close()  # a killed call's
            shown = []
            with self.assertWarnsRegex(UserWarning, "discarding 3 files"):
                viscor.dask.table(SPEC, spread, self.client, shards=2, progress=lambda d, t: shown.append((d, t)))
            self.assertEqual(shown, [(0, 2), (1, 2), (2, 2)])  # the finished shards, as they come
            with open(one, "rb") as a, open(spread, "rb") as b:
                self.assertEqual(a.read(), b.read())
            self.assertFalse(os.path.exists(spread + ".shards"))
            self.assertFalse(os.path.exists(spread + ".shards.lock"))

    def test_a_file_it_did_not_write_is_refused_and_kept(self):
        with tempfile.TemporaryDirectory() as tmp:
            spread = os.path.join(tmp, "spread.csv")
            os.makedirs(spread + ".shards")
            notes = os.path.join(spread + ".shards", "notes.txt")
            with open(notes, "w") as f:
                f.write("mine\n")
            with self.assertRaisesRegex(viscor.Error, "notes.txt' is not a shard"):
                viscor.dask.table(SPEC, spread, self.client, shards=2)
            with open(notes) as f:
                self.assertEqual(f.read(), "mine\n")
            self.assertFalse(os.path.exists(spread))

    def test_a_second_call_on_the_same_output_stops_at_once(self):
        with tempfile.TemporaryDirectory() as tmp:
            spread = os.path.join(tmp, "spread.csv")
            os.makedirs(spread + ".shards")
            with viscor._viscor.OutputLock(spread + ".shards"):  # another call, as far as this one can tell
                with self.assertRaisesRegex(viscor.Error, "another viscor is writing"):
                    viscor.dask.table(SPEC, spread, self.client, shards=2)
            self.assertFalse(os.path.exists(spread))
            with viscor._viscor.OutputLock(spread):  # a table run or a merge writing the output itself
                with self.assertRaisesRegex(viscor.Error, "another viscor is writing"):
                    viscor.dask.table(SPEC, spread, self.client, shards=2)
            self.assertFalse(os.path.exists(spread))

    def test_tasks_keep_their_scratch_in_the_workers_directory(self):
        # Dask removes a worker's local directory when its process is gone, so a task
        # killed with its worker leaves no scratch folder behind.
        used = self.client.submit(viscor.dask._scratch_root, pure=False).result()
        local = self.client.run(lambda dask_worker: dask_worker.local_directory).values()
        self.assertIn(used, list(local))
        self.assertIsNone(viscor.dask._scratch_root())  # outside a worker: the system's temporary directory

    def test_points_and_evaluate_equal_one_process(self):
        points = [{"law": "tsuji", "gamma": str(0.01 * k), "g": "0.5"} for k in range(10)] + \
                 [{"law": "linear", "gamma": "-1"}]
        shown = []
        mine = viscor.dask.cor_points(points, self.client, chunk=3, digits=20, progress=lambda d, t: shown.append((d, t)))
        self.assertEqual(shown[-1], (len(points), len(points)))
        ref = viscor.cor_points(points, digits=20)
        self.assertEqual([without_timings(r) for r in mine], [without_timings(r) for r in ref])
        gamma = np.linspace(1e-3, 0.2, 500)
        spread = viscor.dask.evaluate(self.client, "tsuji", gamma, 0.7, tol=1e-8, chunk=128)
        local = viscor.evaluate("tsuji", gamma, 0.7, tol=1e-8)
        for field in ("e", "one_minus_e", "empirical_bound", "method", "outcome"):
            self.assertTrue(np.array_equal(getattr(spread, field), getattr(local, field)), field)


if __name__ == "__main__":
    unittest.main()
