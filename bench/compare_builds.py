#!/usr/bin/env python3
"""Two builds of obbsat_bench in one run, alternating, so that a change is judged against the same machine state.

Usage: compare_builds.py BEFORE_BENCH AFTER_BENCH --filter REGEX [--rounds N] [--min-time S] [--out FILE.json]

Each round runs BEFORE then AFTER on the same filter (one repetition each, --benchmark_min_time S), so drift of
the machine falls on both builds alike. Prints, per benchmark, the median real time of each build over the rounds,
their ratio AFTER / BEFORE and the spread of each build (largest over smallest round), and writes every round's
times as JSON when --out is given. A row that only one build has is reported and left out of the ratios.
"""

import argparse
import json
import statistics
import subprocess
import sys
import tempfile


def run_once(bench, bench_filter, min_time):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        command = [bench, f"--benchmark_filter={bench_filter}", f"--benchmark_min_time={min_time}",
                   f"--benchmark_out={out.name}", "--benchmark_out_format=json"]
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if done.returncode != 0:
            sys.exit(f"compare_builds.py: {bench} failed (exit {done.returncode}): {done.stderr.strip()}")
        with open(out.name) as f:
            report = json.load(f)
    return report["context"], {b["name"]: b["real_time"] for b in report["benchmarks"] if b.get("run_type") == "iteration"}


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--filter", required=True)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--min-time", type=float, default=0.2)
    parser.add_argument("--out")
    args = parser.parse_args()
    if args.rounds < 1:
        sys.exit("compare_builds.py: --rounds must be at least 1")

    times = {"before": {}, "after": {}}
    context = None
    for round_number in range(args.rounds):
        for side, bench in (("before", args.before), ("after", args.after)):
            context, rows = run_once(bench, args.filter, args.min_time)
            for name, value in rows.items():
                times[side].setdefault(name, []).append(value)
        print(f"round {round_number + 1} of {args.rounds} done", file=sys.stderr)

    names = [n for n in times["before"] if n in times["after"]]
    for side in ("before", "after"):
        for name in times[side]:
            if name not in names:
                print(f"only in {side}: {name}")
    width = max((len(n) for n in names), default=10)
    print(f"CPU: {cpu_model()}; {args.rounds} alternating rounds, medians")
    print(f"{'benchmark':<{width}}  {'before':>12}  {'after':>12}  {'after/before':>12}  {'spread b/a':>12}")
    ratios = []
    for name in names:
        before, after = statistics.median(times["before"][name]), statistics.median(times["after"][name])
        spread = (max(times["before"][name]) / min(times["before"][name]),
                  max(times["after"][name]) / min(times["after"][name]))
        ratios.append(after / before)
        print(f"{name:<{width}}  {before:12.4g}  {after:12.4g}  {after / before:12.3f}  {spread[0]:5.2f}/{spread[1]:<5.2f}")
    if ratios:
        print(f"geometric mean of after/before over {len(ratios)} rows: {statistics.geometric_mean(ratios):.3f}")
    if args.out:
        with open(args.out, "w") as f:
            json.dump({"context": context, "filter": args.filter, "rounds": args.rounds, "times": times}, f, indent=1)


if __name__ == "__main__":
    main()
