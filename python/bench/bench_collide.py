"""Throughput of obbsat.collide from Python against the same call in C++.

Both sides build the same seeded scene (obbsat::make_scene: PAIRS candidate
pairs over PAIRS / 2 rectangles, typical density, seed 1) and time
collide_pairs over it on the best backend, 1 and 2 threads, best of
--repeats runs. Python is timed three ways, each against the C++ call it
makes: a float32 array read in place as numpy placed it and as
obbsat.aligned copied it (C++ collide_pairs over a rect array; both check
the coordinates on each call), a RectRecords store (C++
collide_pairs over rect_records, checked once), and, for the conversion
cost, float64 corners with int64 pairs rounded to float32 on request
(precision="float32", against the rect array call).

    python3 python/bench/bench_collide.py --cpp build/python/obbsat_collide_baseline
"""

import argparse
import subprocess
import threading
import time

import numpy as np

import obbsat


def best_of(repeats, call):
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        best = min(best, time.perf_counter() - start)
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--method", default="sat4")
    parser.add_argument("--cpp", help="the obbsat_collide_baseline program, for the C++ figures")
    args = parser.parse_args()

    rects, pairs = obbsat.testing.make_scene(rects=args.pairs // 2, pairs=args.pairs, seed=1)
    store = obbsat.records(rects)
    aligned = obbsat.aligned(rects)
    out = np.empty(len(pairs), dtype=bool)
    backend = obbsat.resolved_backend()
    print(f"scene: {len(rects)} rectangles, {len(pairs)} pairs; method {args.method}; backend {backend}")

    cpp = {}
    if args.cpp:
        done = subprocess.run([args.cpp, "--pairs", str(args.pairs), "--repeats", str(args.repeats),
                               "--method", args.method], check=True, capture_output=True, text=True)
        for line in done.stdout.splitlines():
            fields = dict(f.split("=") for f in line.split())
            cpp[(fields["call"], int(fields["threads"]))] = (float(fields["seconds"]), int(fields["hits"]))

    wide_rects, wide_pairs = rects.astype(np.float64), pairs.astype(np.int64)
    hits = None
    print("| threads | call | ms | Mpairs/s | vs the same C++ call |")
    print("|---:|---|---:|---:|---:|")
    for threads in (1, 2):
        rows = [
            ("C++ collide_pairs(rect_records)", "records", None),
            ("C++ collide_pairs(rect*, count)", "array", None),
            (f"obbsat.collide(float32 array at {rects.ctypes.data % 64} mod 64, uint32 pairs)", "array",
             lambda: obbsat.collide(rects, pairs, method=args.method, threads=threads, out=out)),
            ("obbsat.collide(obbsat.aligned(float32 array), uint32 pairs)", "array",
             lambda: obbsat.collide(aligned, pairs, method=args.method, threads=threads, out=out)),
            ("obbsat.collide(RectRecords, uint32 pairs)", "records",
             lambda: obbsat.collide(store, pairs, method=args.method, threads=threads, out=out)),
            ("obbsat.collide(float64 array as float32, int64 pairs)", "array",
             lambda: obbsat.collide(wide_rects, wide_pairs, method=args.method, threads=threads, out=out,
                                    precision="float32")),
        ]
        for name, peer, call in rows:
            key = (peer, threads)
            if call is None:
                if key not in cpp:
                    continue
                seconds = cpp[key][0]
            else:
                seconds = best_of(args.repeats if "float64" not in name else max(3, args.repeats // 4), call)
                hits = int(out.sum())
                if key in cpp and hits != cpp[key][1]:
                    raise SystemExit(f"{name}: {hits} hits, C++ found {cpp[key][1]}")
            ratio = f"{seconds / cpp[key][0]:.2f}x" if key in cpp else "-"
            print(f"| {threads} | {name} | {seconds * 1e3:.2f} | {len(pairs) / seconds / 1e6:.1f} | {ratio} |")

    # Two Python threads, each deciding the whole list on one core at once.
    outs = [np.empty(len(pairs), dtype=bool) for _ in range(2)]

    def twice():
        workers = [threading.Thread(target=lambda o=o: obbsat.collide(rects, pairs, method=args.method, out=o))
                   for o in outs]
        for w in workers:
            w.start()
        for w in workers:
            w.join()

    one = best_of(args.repeats, lambda: obbsat.collide(rects, pairs, method=args.method, out=outs[0]))
    two = best_of(args.repeats, twice)
    print(f"two Python threads, 1 core each: {2 * len(pairs) / two / 1e6:.1f} Mpairs/s together, "
          f"{len(pairs) / one / 1e6:.1f} from one thread alone ({one * 2 / two:.2f}x)")
    print(f"hits: {hits} of {len(pairs)}")


if __name__ == "__main__":
    main()
