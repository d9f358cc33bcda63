"""vct-cluster: path-traced references and validate sweeps as tasks on Dask (docs/cluster.md).

Each task runs the `vct` binary with a worker's cores; results are files (partial sums, sweep
rows) sent back to the client, which merges them in a fixed order so the bytes do not depend on
the number of workers, the order tasks finish or retries. Dask is imported only by
`executors.py` when a --scheduler other than `none` is asked for: nothing else in vct imports it.
"""
