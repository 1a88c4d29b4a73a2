"""The cost of one Dask chunk: obbsat.dask.collide on a LocalCluster of two
worker processes, the same pair list cut into ever more chunks, against one
obbsat.collide call in this process. The overhead per chunk is the slope of
wall time over the number of chunks.

    python3 python/bench/bench_dask.py --pairs 2000000
"""

import argparse
import time

import dask.array as da
import distributed
import obbsat
import obbsat.dask


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=2_000_000)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    rects, pairs = obbsat.testing.make_scene(rects=args.pairs // 2, pairs=args.pairs, seed=1)
    expected = obbsat.collide(rects, pairs)
    single = float("inf")
    for _ in range(args.repeats):
        start = time.perf_counter()
        obbsat.collide(rects, pairs)
        single = min(single, time.perf_counter() - start)
    print(f"one obbsat.collide call, {len(pairs)} pairs, this process: {single * 1e3:.1f} ms")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        start = time.perf_counter()
        store = obbsat.dask.shared_records(rects, client)
        distributed.wait(store)
        print(f"checking and broadcasting {len(rects)} rectangles ({rects.nbytes / 2**20:.0f} MB) to 2 workers: "
              f"{(time.perf_counter() - start) * 1e3:.0f} ms")
        lazy_pairs = {}
        print("| chunks | pairs per chunk | wall ms (best of repeats) |")
        print("|---:|---:|---:|")
        points = []
        for chunks in (2, 8, 32, 128, 512):
            per_chunk = -(-len(pairs) // chunks)
            lazy_pairs = client.persist(da.from_array(pairs, chunks=(per_chunk, 2)))
            distributed.wait(lazy_pairs)
            best = float("inf")
            for _ in range(args.repeats):
                start = time.perf_counter()
                got = obbsat.dask.collide(store, lazy_pairs).compute()
                best = min(best, time.perf_counter() - start)
            if got.tobytes() != expected.tobytes():
                raise SystemExit("verdicts differ from the single-process call")
            points.append((chunks, best))
            print(f"| {chunks} | {per_chunk} | {best * 1e3:.1f} |")
        for (c0, t0), (c1, t1) in zip(points, points[1:]):
            print(f"from {c0} to {c1} chunks: {(t1 - t0) / (c1 - c0) * 1e3:.2f} ms more per added chunk")

if __name__ == "__main__":
    main()
