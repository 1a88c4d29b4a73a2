"""Time of the scene query from Python on one seeded scene: an array of poses
(read in place), a PoseRecords store, the same boxes as corners, and a
PairFinder over frames in which every box moved a little; 1 and 2 threads,
best of --repeats runs, every answer checked equal.

    python3 python/bench/bench_find_pairs.py --boxes 1000000
"""

import argparse
import time

import numpy as np

import obbsat


def best_of(repeats, call):
    best = float("inf")
    result = None
    for _ in range(repeats):
        start = time.perf_counter()
        result = call()
        best = min(best, time.perf_counter() - start)
    return best, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--boxes", type=int, default=1_000_000)
    parser.add_argument("--sizes", default="uniform", choices=["uniform", "mixed"])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--method", default="exact")
    args = parser.parse_args()

    poses = obbsat.testing.make_pose_scene(boxes=args.boxes, sizes=args.sizes, seed=1)
    store = obbsat.records(poses)
    corners = obbsat.corners_of_poses(poses).reshape(-1, 8)
    rng = np.random.default_rng(2)
    frames = []
    frame = poses.copy()
    for _ in range(args.repeats + 1):
        frame = frame.copy()
        frame[:, :2] += rng.uniform(-0.01, 0.01, size=(len(frame), 2)).astype(np.float32)
        frames.append(frame)

    print(f"{args.boxes} boxes ({args.sizes} sizes), method {args.method}, backend {obbsat.resolved_backend()}")
    print("| call | threads | ms | ns per box | pairs |")
    print("|---|---:|---:|---:|---:|")
    for threads in (1, 2):
        expected = None
        rows = [
            ("find_pairs(float32 (N, 6) array, read in place)", lambda: obbsat.find_pairs(
                poses, method=args.method, threads=threads)),
            ("find_pairs(PoseRecords)", lambda: obbsat.find_pairs(store, method=args.method, threads=threads)),
            ("find_pairs(float32 (N, 8) corners, read in place)", lambda: obbsat.find_pairs(
                corners, method=args.method, threads=threads)),
        ]
        for name, call in rows:
            seconds, pairs = best_of(args.repeats, call)
            if "corners" not in name:
                if expected is None:
                    expected = pairs
                elif not np.array_equal(pairs, expected):
                    raise SystemExit(f"{name}: a different answer")
            print(f"| `{name}` | {threads} | {seconds * 1e3:.1f} | {seconds * 1e9 / args.boxes:.0f} | {len(pairs)} |")
        finder = obbsat.PairFinder(method=args.method, threads=threads)
        finder.find(frames[0])
        times = []
        for f in frames[1:]:
            start = time.perf_counter()
            pairs = finder.find(f)
            times.append(time.perf_counter() - start)
        if not np.array_equal(pairs, obbsat.find_pairs(frames[-1], method=args.method)):
            raise SystemExit("PairFinder: a different answer from a fresh query")
        seconds = min(times)
        print(f"| `PairFinder.find(array)`, every box moved by up to 0.01 | {threads} | {seconds * 1e3:.1f} | "
              f"{seconds * 1e9 / args.boxes:.0f} | {len(pairs)} |")


if __name__ == "__main__":
    main()
