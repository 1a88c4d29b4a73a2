#!/usr/bin/env python3
"""Turn an obbsat_bench results JSON (--benchmark_out_format=json) into markdown.

Usage: summarize.py RESULTS.json [> RESULTS.md]

Rows are the medians of the repetitions when the run has aggregates, else the
single runs. For each obbsat benchmark: Mpairs/s and ns/pair, the speedup over
the scalar backend of the same method, mode, store, size, threads and density,
and over Box2D's b2CollidePolygons on the same pairs (single-threaded, so a
threads:2 row's figure includes the second core). Peers get a table of their
own with their agreement with the sat4 scalar reference. Whole-scene rows
(scene/, frame/, peer_scene/, peer_frame/) get a table of ns per box, pairs
and candidates per box, and the time against obbsat's exact on poses for the
same query, scene and threads.
"""

import json
import sys

BACKEND_ORDER = {"scalar": 0, "sse2": 1, "avx2": 2, "avx512": 3}
MODE_ORDER = {"stream": 0, "indexed_sorted": 1, "indexed_random": 2}
DENSITY_ORDER = {"typical": 0, "sparse": 1, "dense": 2}
BASELINE_PEER = "box2d_collide_polygons"


def fail(message):
    print(f"summarize.py: {message}", file=sys.stderr)
    sys.exit(1)


def parse_fields(parts, where):
    """'pairs:4096' style components into a dict."""
    fields = {}
    for part in parts:
        key, sep, value = part.partition(":")
        if not sep:
            fail(f"{where}: unexpected name component '{part}'")
        fields[key] = value
    return fields


def parse_name(run_name):
    """The parts of a benchmark name, or None for names this script does not know."""
    parts = run_name.split("/")
    if parts and parts[-1] in ("real_time", "manual_time"):
        parts = parts[:-1]
    if len(parts) >= 6 and parts[0] == "collide":
        fields = parse_fields(parts[4:], run_name)
        return {
            "kind": "collide",
            "method": parts[1],
            "mode": parts[2],
            "backend": parts[3],
            "pairs": int(fields["pairs"]),
            "threads": int(fields["threads"]),
            "density": fields.get("density", "typical"),
            "store": fields.get("store", "soa" if parts[2] == "stream" else "records"),
        }
    if len(parts) >= 6 and parts[0] in ("scene", "frame"):
        fields = parse_fields(parts[3:], run_name)
        return {"kind": "scene", "query": "cold" if parts[0] == "scene" else "frame",
                "who": f"{parts[1]}/{parts[2]}", "boxes": int(fields["boxes"]), "sizes": fields["sizes"],
                "threads": int(fields["threads"])}
    if len(parts) >= 5 and parts[0] in ("peer_scene", "peer_frame"):
        fields = parse_fields(parts[2:], run_name)
        return {"kind": "scene", "query": "cold" if parts[0] == "peer_scene" else "frame",
                "who": f"peer {parts[1]}", "boxes": int(fields["boxes"]), "sizes": fields["sizes"],
                "threads": int(fields["threads"])}
    if len(parts) >= 3 and parts[0] == "peer":
        fields = parse_fields(parts[2:], run_name)
        return {"kind": "peer", "peer": parts[1], "pairs": int(fields["pairs"])}
    return None


def select_rows(benchmarks):
    """Median aggregates if there are any, else the plain runs; errors dropped."""
    medians = [b for b in benchmarks
               if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median"]
    rows = medians if medians else [b for b in benchmarks if b.get("run_type") == "iteration"]
    errors = [b for b in benchmarks if b.get("error_occurred")]
    return [b for b in rows if not b.get("error_occurred")], errors, bool(medians)


def size_text(pairs):
    if pairs % (1 << 20) == 0:
        return f"{pairs >> 20}M"
    if pairs % (1 << 10) == 0:
        return f"{pairs >> 10}K"
    return str(pairs)


def ratio_text(numerator, denominator):
    if numerator is None or not denominator:
        return "–"
    return f"{numerator / denominator:.1f}×"


def main(argv):
    if len(argv) != 2:
        fail("usage: summarize.py RESULTS.json")
    path = argv[1]
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror}")
    except json.JSONDecodeError as e:
        fail(f"{path}:{e.lineno}: not valid JSON: {e.msg}")
    if not isinstance(data, dict) or "benchmarks" not in data:
        fail(f"{path}: no 'benchmarks' array: not a Google Benchmark JSON file")

    context = data.get("context", {})
    rows, errors, have_medians = select_rows(data["benchmarks"])

    collide = {}
    peers = {}
    scenes = {}
    for row in rows:
        name = parse_name(row.get("run_name", row.get("name", "")))
        if name is not None and name["kind"] == "scene" and "ns_per_box" in row:
            scenes[(name["query"], name["boxes"], name["sizes"], name["threads"], name["who"])] = row
            continue
        if name is None or "pairs_per_second" not in row:
            continue
        if name["kind"] == "collide":
            key = (name["method"], name["mode"], name["store"], name["density"], name["pairs"],
                   name["threads"], name["backend"])
            collide[key] = row
        else:
            peers[(name["peer"], name["pairs"])] = row

    def rate_of(row):
        return row["pairs_per_second"] if row else None

    out = []
    out.append(f"# obbsat_bench results: {path}")
    out.append("")
    out.append(f"- date: {context.get('date', '?')}, host: {context.get('host_name', '?')}, "
               f"{context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz, "
               f"load average at start: {', '.join(f'{x:.2f}' for x in context.get('load_avg', []))}")
    out.append(f"- obbsat build: {context.get('obbsat_build_type', '?')}; backends compiled: "
               f"{context.get('obbsat_compiled_backends', '?')}; best here: "
               f"{context.get('obbsat_best_backend', '?')}")
    out.append(f"- figures: {'median of the repetitions' if have_medians else 'single runs (no repetitions)'}"
               ", real time")
    out.append("")

    if collide:
        out.append("## obbsat")
        out.append("")
        out.append(f"| method | mode | store | density | pairs | threads | backend | Mpairs/s | ns/pair "
                   f"| × scalar | × {BASELINE_PEER} |")
        out.append("|---|---|---|---|---:|---:|---|---:|---:|---:|---:|")
        for key in sorted(collide, key=lambda k: (k[0], MODE_ORDER.get(k[1], 9), k[2],
                                                   DENSITY_ORDER.get(k[3], 9), k[4], k[5],
                                                   BACKEND_ORDER.get(k[6], 9))):
            method, mode, store, density, pairs, threads, backend = key
            row = collide[key]
            scalar = collide.get((method, mode, store, density, pairs, threads, "scalar"))
            peer = peers.get((BASELINE_PEER, pairs)) if density == "typical" else None
            rate = rate_of(row)
            out.append(f"| {method} | {mode} | {store} | {density} | {size_text(pairs)} | {threads} | {backend} "
                       f"| {rate / 1e6:.1f} | {row['ns_per_pair']:.2f} "
                       f"| {ratio_text(rate, rate_of(scalar))} | {ratio_text(rate, rate_of(peer))} |")
        out.append("")

    if peers:
        out.append("## Peers (single-threaded, indexed_sorted pair list, typical density)")
        out.append("")
        out.append("| peer | pairs | Mpairs/s | ns/pair | agreement with sat4 | peer only | reference only "
                   f"| × {BASELINE_PEER} |")
        out.append("|---|---:|---:|---:|---:|---:|---:|---:|")
        for (peer, pairs) in sorted(peers, key=lambda k: (k[1], k[0])):
            row = peers[(peer, pairs)]
            base = peers.get((BASELINE_PEER, pairs))
            out.append(f"| {peer} | {size_text(pairs)} | {row['pairs_per_second'] / 1e6:.2f} "
                       f"| {row['ns_per_pair']:.1f} | {row.get('agreement', float('nan')):.6f} "
                       f"| {row.get('peer_only', float('nan')):.6f} "
                       f"| {row.get('reference_only', float('nan')):.6f} "
                       f"| {ratio_text(rate_of(row), rate_of(base))} |")
        out.append("")

    if scenes:
        out.append("## Whole scenes: poses to colliding pairs")
        out.append("")
        out.append("cold: a fresh query each time; frame: a query kept while every box moves a little. "
                   "× exact/poses: this row's time over obbsat's exact on poses (same query, scene, threads).")
        out.append("")
        out.append("| query | boxes | sizes | threads | who | ms | ns/box | pairs/box | candidates/box "
                   "| reused order | agreement | × exact/poses |")
        out.append("|---|---:|---|---:|---|---:|---:|---:|---:|---:|---:|---:|")
        for key in sorted(scenes, key=lambda k: (k[0] != "cold", k[1], k[2], k[3], k[4].startswith("peer"), k[4])):
            query, boxes, sizes, threads, who = key
            row = scenes[key]
            base = scenes.get((query, boxes, sizes, threads, "exact/poses"))
            reused = f"{row['reused_order']:.2f}" if "reused_order" in row else "–"
            agreement = f"{row['agreement']:.6f}" if "agreement" in row else "–"
            versus = ratio_text(row["ns_per_box"], base["ns_per_box"] if base else None)
            out.append(f"| {query} | {size_text(boxes)} | {sizes} | {threads} | {who} "
                       f"| {row['ns_per_box'] * boxes * 1e-6:.2f} | {row['ns_per_box']:.1f} "
                       f"| {row.get('pairs_per_box', float('nan')):.3f} "
                       f"| {row.get('candidates_per_box', float('nan')):.3f} | {reused} | {agreement} | {versus} |")
        out.append("")

    if errors:
        out.append("## Benchmarks that reported an error")
        out.append("")
        for b in errors:
            out.append(f"- {b.get('name', '?')}: {b.get('error_message', '?')}")
        out.append("")

    if not collide and not peers and not scenes:
        fail(f"{path}: no obbsat_bench results in it")
    sys.stdout.write("\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
