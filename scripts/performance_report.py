#!/usr/bin/env python3
"""Writes docs/performance.md from the Google Benchmark JSON files in bench/results.

Usage: performance_report.py RESULTS_DIR OUTPUT_MD  (scripts/bench.sh calls it)

Reads step_bench_double.json, step_bench_float.json, neighbor_bench_double.json and the A/B pairs
listed in optimisations.json; every number on the page comes from those files, medians over the
repetitions (a single run where there is only one). Draws docs/performance/*.png with matplotlib,
puts targets_not_met.md (each target not met: its figure, the profile that explains it, what was
tried) under the targets table and appends notes.md (the analysis) and profiling.md (how to
profile a scene).
"""

import json
import os
import re
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Issue 8's reference figures, measured on this 2-core machine class.
SPH_WCSPH_2T = 0.93e6  # SPlisHSPlasH 2.16, float, particle-steps/s, 2 threads
SPH_DFSPH_2T = 0.74e6
DAM_BREAK_LIMITS = {("wcsph", 40): 6.6, ("wcsph", 80): 35.0, ("dfsph", 40): 1.9, ("dfsph", 80): 8.7}
# The BM_Feature entries whose *off* side is the plain dam break (the same step each time).
PLAIN_OFF = ["artificial_stress", "laminar_viscosity", "multiple_phases", "no_slip_walls", "shifting",
             "surface_tension_akinci"]
DAM_BREAK_REFERENCE = {("wcsph", 40): 19.9, ("wcsph", 80): 104.0, ("dfsph", 40): 5.6, ("dfsph", 80): 26.0}


def repetitions(path):
    """Benchmark name -> its rows (one per repetition), errors and aggregates left out, plus the context."""
    if not os.path.exists(path):
        return {}, {}
    with open(path) as f:
        data = json.load(f)
    runs = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" or b.get("error_occurred"):
            continue
        # "…/iterations:20/real_time" is how the run was timed, not which benchmark it is.
        name = re.sub(r"/(iterations:\d+|real_time|repeats:\d+)", "", b.get("run_name", b["name"]))
        runs.setdefault(name, []).append(b)
    return runs, data.get("context", {})


def load(path):
    """Benchmark name -> {counter: median over the repetitions}, with time_unit and repetitions."""
    runs, context = repetitions(path)
    medians = {}
    for name, rows in runs.items():
        keys = [k for k, v in rows[0].items() if isinstance(v, (int, float)) and not isinstance(v, bool)]
        medians[name] = {k: statistics.median(r[k] for r in rows if k in r) for k in keys}
        medians[name]["time_unit"] = rows[0].get("time_unit", "ns")
        medians[name]["repetitions"] = len(rows)
        rates = [r["particle-steps/s"] for r in rows if "particle-steps/s" in r]
        if rates:
            medians[name]["rate_range"] = (min(rates), max(rates))
    return medians, context


def load_best(path):
    """Benchmark name -> the fastest repetition in ms: on a shared machine the least disturbed run."""
    runs, _ = repetitions(path)
    return {name: min(ms({**r, "time_unit": r.get("time_unit", "ns")}) for r in rows) for name, rows in runs.items()}


def load_memory(results_dir, name):
    """bench/memory_report --json output, or None."""
    path = os.path.join(results_dir, name)
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def ms(row):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[row["time_unit"]]
    return row["real_time"] * scale


def mega(x):
    return f"{x / 1e6:.2f} M"


def status(ok):
    """A target's status; one not met links to its figure, profile and what was tried."""
    return "**met**" if ok else "not met ([why](#the-targets-not-met-figure-profile-what-was-tried))"


def rate_with_range(row):
    """The median particle-steps/s, with the range over the repetitions when there are several."""
    low, high = row.get("rate_range", (row["particle-steps/s"],) * 2)
    n = row["repetitions"]
    return mega(row["particle-steps/s"]) + (f", median of {n} runs: {low / 1e6:.2f}–{high / 1e6:.2f} M" if n > 1 else "")


def rate_status(row, target):
    """Met, met at the median only (some repetitions below the target), or not met."""
    if row["particle-steps/s"] < target:
        return status(False)
    low = row.get("rate_range", (row["particle-steps/s"],))[0]
    return status(True) + ("" if low >= target else " at the median, not in every run")


def step_rows(results, scheme, dim, threads):
    pattern = re.compile(rf"BM_Step/{scheme}/{dim}D/N:(\d+)/threads:{threads}/")
    rows = []
    for name, row in results.items():
        m = pattern.match(name)
        if m:
            rows.append((int(m.group(1)), name, row))
    return sorted(rows)


def fmt_share(row, key):
    return f"{100 * row.get(key, 0):.1f}%"


def write_memory(w, after, before, without_skin):
    """The itemised bytes per fluid particle of bench/memory_report: before issue 8's memory work,
    after it (the default skin) and, if measured, after it with lists rebuilt every step (skin 0)."""
    w("## Where the bytes go\n")
    w(f"{after['dimension']}D {after['scheme'].upper()}, {after['real']}, the dam break of `step_bench` at "
      f"{after['fluid']:,} fluid and {after['walls']:,} wall particles, after {after['steps']} steps: every buffer "
      "the simulation keeps, at its capacity (`Simulation::memory_usage`), in bytes per fluid particle. "
      "Reproduce: `build/bench/memory_report --particles 1000000 --json bench/results/memory_report.json` "
      "(about a minute on 2 cores); `memory_report_before.json` is the same program on the code before the "
      "changes below (commit f549d25, which only added the accounting), `memory_report_skin0.json` the "
      "current code with `--skin 0` (`solver.neighbor_skin: 0`: no candidate lists, the fluid sorted and "
      "its lists rebuilt every step).\n")
    columns = [(label, report) for label, report in (("before", before), ("after", after),
                                                      ("after, skin 0", without_skin)) if report]
    names = []
    for _, report in columns:
        names += [i["name"] for i in report["items"] if i["name"] not in names]
    value = lambda report, name: next((i["bytes_per_particle"] for i in report["items"] if i["name"] == name), None)
    cell = lambda v: "—" if v is None or v == 0 else f"{v:.1f}"
    w("| item | " + " | ".join(label for label, _ in columns) + " |")
    w("|---|" + "--:|" * len(columns))
    for name in names:
        values = [value(report, name) for _, report in columns]
        if any(values):
            w(f"| {name} | " + " | ".join(cell(v) for v in values) + " |")
    w("| **total held** | " + " | ".join(f"**{r['bytes_per_particle']:.1f}**" for _, r in columns) + " |")
    for label, key in (("resident after the steps (VmRSS)", "rss_after_steps"),
                       ("resident peak of the steps (VmHWM, reset after the build)", "rss_peak_steps"),
                       ("freed, kept by the C allocator", "heap_free_kept")):
        w(f"| {label} | " + " | ".join(f"{r[key]:.1f}" if key in r else "" for _, r in columns) + " |")
    w("")


def include(w, results_dir, page):
    """Appends a hand-written page of bench/results/, if it exists."""
    path = os.path.join(results_dir, page)
    if os.path.exists(path):
        with open(path) as f:
            w(f.read())


def main():
    results_dir, output = sys.argv[1], sys.argv[2]
    double, context = load(os.path.join(results_dir, "step_bench_double.json"))
    single, _ = load(os.path.join(results_dir, "step_bench_float.json"))
    neighbor, _ = load(os.path.join(results_dir, "neighbor_bench_double.json"))
    memory = load_memory(results_dir, "memory_report.json")
    memory_before = load_memory(results_dir, "memory_report_before.json")
    memory_without_skin = load_memory(results_dir, "memory_report_skin0.json")
    figures = os.path.join(os.path.dirname(output), "performance")
    os.makedirs(figures, exist_ok=True)
    out = []
    w = out.append

    w("# Performance\n")
    w("Generated by `scripts/bench.sh` (run and write) or `scripts/bench.sh --report` (write only) from the")
    w("Google Benchmark output in `bench/results/`; do not edit by hand. Vocabulary as in DESIGN.md:")
    w("particle-steps/s = fluid particles × steps / wall s (walls not counted), ns per")
    w("particle–neighbour interaction = step time / (fluid–fluid + fluid–wall pairs), bytes per fluid")
    w("particle including walls and every neighbour structure. Medians over the repetitions.\n")
    if context:
        w(f"Machine: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz, "
          f"run {context.get('date', '?')}, "
          f"load average at start {', '.join(f'{x:.2f}' for x in context.get('load_avg', []))}. "
          "The machine is shared: a row whose `cpu_util` is well below 1 was disturbed.\n")

    # ---- Targets -------------------------------------------------------------------------
    w("## Targets of issue 8\n")
    w("| # | target | measured | reference | status | reproduce |")
    w("|---|---|---|---|---|---|")
    ref = {k: double.get(f"BM_Reference3D/{k}/threads:2/double") for k in ("wcsph", "dfsph", "iisph")}
    ref1 = double.get("BM_Reference3D/wcsph/threads:1/double")
    ref_float = single.get("BM_Reference3D/wcsph/threads:2/float")
    cmd_ref = "`step_bench --benchmark_filter=BM_Reference3D`"
    if ref["wcsph"]:
        v = ref["wcsph"]["particle-steps/s"]
        w(f"| 1 | WCSPH 3D reference, double, 2 threads ≥ 3 M particle-steps/s | {rate_with_range(ref['wcsph'])} "
          f"({v / SPH_WCSPH_2T:.2f}× SPlisHSPlasH) | 0.93 M | {rate_status(ref['wcsph'], 3e6)} | {cmd_ref} |")
    if ref_float:
        v = ref_float["particle-steps/s"]
        w(f"| 1 | the same in float ≥ 4.5 M | {rate_with_range(ref_float)} | 0.93 M | {rate_status(ref_float, 4.5e6)} "
          f"| float build, {cmd_ref} |")
    if ref["dfsph"]:
        r = ref["dfsph"]
        v = r["particle-steps/s"]
        w(f"| 2 | DFSPH 3D reference at 0.05% mean density error: wall time per simulated second ≤ ½ "
          f"SPlisHSPlasH's | {mega(v)} particle-steps/s, {r['density_iter']:.1f} density + "
          f"{r['divergence_iter']:.1f} divergence iterations, {r['wall_per_sim_s']:.1f} wall s per simulated s "
          f"| 0.74 M at 2.3 + 5 iterations | {status(v >= 2 * SPH_DFSPH_2T)} (as particle-steps/s ≥ 1.48 M; "
          f"its time step is not published) | {cmd_ref} |")
    for (scheme, res), limit in DAM_BREAK_LIMITS.items():
        row = double.get(f"BM_DamBreak2D/{scheme}/a_dx:{res}/threads:2/double")
        if not row:
            continue
        wall = row["wall_s"]
        w(f"| 2 | 2D dam break {scheme.upper()} a/Δx = {res} to T = 3 ≤ {limit} s | {wall:.2f} s "
          f"(front error {100 * row['front_error']:.1f}%) | {DAM_BREAK_REFERENCE[(scheme, res)]} s | "
          f"{status(wall <= limit)} | `step_bench --benchmark_filter=BM_DamBreak2D/{scheme}/a_dx:{res}` |")
    wc3 = step_rows(double, "wcsph", 3, 2)
    if ref["wcsph"]:
        f = ref["wcsph"]["f_nbr"]
        w(f"| 3 | neighbour search ≤ 20% of a WCSPH step (reference scene) | {100 * f:.1f}% | about 50% | "
          f"{status(f <= 0.2)} | {cmd_ref} |")
    if wc3:
        per = [(n, 1e9 / row["particle-steps/s"]) for n, _, row in wc3]
        base = dict(per).get(1_000_000, per[-1][1])
        spread = max(abs(t / base - 1) for _, t in per)
        w(f"| 4 | time per particle-step within ±25% from 10^4 to 10^{len(str(per[-1][0])) - 1} (3D WCSPH) | "
          + ", ".join(f"{t:.0f} ns at {n:,}" for n, t in per)
          + f" (largest deviation from 10^6: {100 * spread:.0f}%) | | {status(spread <= 0.25)} | "
          "`step_bench --benchmark_filter='BM_Step/wcsph/3D/.*threads:2'` |")
        big = dict((n, row) for n, _, row in wc3)
        if memory:
            b = memory["bytes_per_particle"]
            w(f"| 4 | bytes per particle ≤ 160 (3D WCSPH, double, 10^6, walls and neighbour structures "
              f"included) | {b:.0f} B held (resident: {memory['rss_after_steps']:.0f} B, peak of a step "
              f"{memory['rss_peak_steps']:.0f} B); see [Where the bytes go](#where-the-bytes-go) | | "
              f"{status(b <= 160)} | `memory_report --particles 1000000`; the `B/particle` counter of "
              "`step_bench --benchmark_filter='BM_Step/wcsph/3D/N:1000000/threads:2'` |")
        elif 1_000_000 in big:
            b = big[1_000_000]["B/particle"]
            w(f"| 4 | bytes per particle ≤ 160 (3D WCSPH, double, 10^6, walls and neighbour structures "
              f"included) | {b:.0f} B | | {status(b <= 160)} | same |")
        one = dict((n, row) for n, _, row in step_rows(double, "wcsph", 3, 1))
        if 1_000_000 in one and 1_000_000 in big:
            s = big[1_000_000]["particle-steps/s"] / one[1_000_000]["particle-steps/s"]
            w(f"| 5 | 2 threads ≥ 1.8× 1 thread at 10^6 (3D WCSPH) | {s:.2f}× | | {status(s >= 1.8)} | "
              "`step_bench --benchmark_filter='BM_Step/wcsph/3D/N:1000000'` |")
    if ref1 and ref["wcsph"]:
        s = ref["wcsph"]["particle-steps/s"] / ref1["particle-steps/s"]
        w(f"| 5 | (the same on the reference scene) | {s:.2f}× | SPlisHSPlasH 2.1× | | {cmd_ref} |")
    w("| 6 | each optional feature: its cost when on, nothing when off | see [Features](#features) | | "
      "see there | `step_bench --benchmark_filter=BM_Feature` |")
    w("")
    include(w, results_dir, "targets_not_met.md")  # hand-written: each target not met, why, what was tried

    # ---- Throughput plot ------------------------------------------------------------------
    w("## Particle-steps per second against particle count\n")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, dim in zip(axes, (2, 3)):
        for scheme, style in (("wcsph", "o-"), ("dfsph", "s-"), ("iisph", "^-")):
            for threads, alpha in ((2, 1.0), (1, 0.45)):
                rows = step_rows(double, scheme, dim, threads)
                if rows:
                    ax.plot([n for n, _, _ in rows], [r["particle-steps/s"] for _, _, r in rows], style, alpha=alpha,
                            label=f"{scheme.upper()}, {threads} thread{'s' if threads > 1 else ''}")
        if dim == 3:
            rows = step_rows(single, "wcsph", 3, 2)
            if rows:
                ax.plot([n for n, _, _ in rows], [r["particle-steps/s"] for _, _, r in rows], "o--",
                        label="WCSPH float, 2 threads")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("fluid particles")
        ax.set_ylabel("particle-steps/s")
        ax.set_title(f"{dim}D dam break, double unless stated")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "throughput.png"), dpi=110)
    w("![particle-steps/s against fluid particle count, per scheme](performance/throughput.png)\n")

    # ---- Per-pass breakdown ---------------------------------------------------------------
    w("## Where the step goes (2 threads, double)\n")
    w("| benchmark | ms/step | particle-steps/s | ns/pair | B/particle | neighbours | search | density | wall | "
      "momentum | solve | integration | shifting | iterations (density + divergence) | cpu_util |")
    w("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    names = [f"BM_Reference3D/{s}/threads:2/double" for s in ("wcsph", "dfsph", "iisph")]
    for scheme in ("wcsph", "dfsph", "iisph"):
        for dim in (2, 3):
            names += [name for _, name, _ in step_rows(double, scheme, dim, 2)]
    for name in names:
        row = double.get(name)
        if not row:
            continue
        iters = f"{row['density_iter']:.1f} + {row['divergence_iter']:.1f}" if row.get("density_iter") else ""
        w(f"| {name} | {ms(row):.2f} | {mega(row['particle-steps/s'])} | {row['ns/pair']:.2f} | "
          f"{row['B/particle']:.0f} | {row['neighbors']:.1f} | {fmt_share(row, 'f_nbr')} | "
          f"{fmt_share(row, 'f_density')} | {fmt_share(row, 'f_wall')} | {fmt_share(row, 'f_momentum')} | "
          f"{fmt_share(row, 'f_solve')} | {fmt_share(row, 'f_integr')} | {fmt_share(row, 'f_shift')} | {iters} | "
          f"{row['cpu_util']:.2f} |")
    w("")
    rows1 = [(name, row) for name, row in double.items() if name.startswith("BM_") and "/threads:1/" in name]
    if rows1:
        w("With 1 thread (speed-up of 2 threads in the last column):\n")
        w("| benchmark | ms/step | particle-steps/s | 2 threads / 1 |")
        w("|---|--:|--:|--:|")
        for name, row in sorted(rows1):
            two = double.get(name.replace("/threads:1/", "/threads:2/"))
            speedup = f"{two['particle-steps/s'] / row['particle-steps/s']:.2f}×" if two else ""
            w(f"| {name} | {ms(row):.2f} | {mega(row['particle-steps/s'])} | {speedup} |")
        w("")

    # ---- Memory ---------------------------------------------------------------------------
    if memory:
        write_memory(w, memory, memory_before, memory_without_skin)

    # ---- Features ---------------------------------------------------------------------------
    feats = {}
    for name, row in double.items():
        m = re.match(r"BM_Feature/(\w+):(on|off)/", name)
        if m:
            feats.setdefault(m.group(1), {})[m.group(2)] = row
    if feats:
        w("## Features\n")
        w("3D dam break at 10^5 particles, WCSPH, 2 threads, double. *off* is the scene without the feature;")
        w("every optional feature is chosen once per pass outside the particle loop (a template flag or a pass")
        w("that is not run), so *off* runs the same instructions as a build in which the feature does not")
        w("exist. `multiple_phases` splits the water block into two materials of the same properties;")
        w("`surface_tension_csf` is csf on that two-fluid scene against it without tension;")
        w("`surface_tension_pairwise` runs both sides with the support of 4 spacings the pair forces need")
        w("(h = 2Δx, 4 wall layers) and `surface_tension_akinci` on the one-fluid scene.\n")
        plain = [ms(feats[f]["off"]) for f in PLAIN_OFF if f in feats and "off" in feats[f]]
        if len(plain) > 1:
            w(f"The *off* rows of {', '.join(f'`{f}`' for f in PLAIN_OFF if f in feats)} are the same scene "
              f"({len(plain)} entries): {min(plain):.2f}–{max(plain):.2f} ms per step, a spread of "
              f"{100 * (max(plain) / min(plain) - 1):.0f}%, which is this run's noise: a cost within it is not "
              "resolved.\n")
        w("| feature | off: ms/step | on: ms/step | cost when on |")
        w("|---|--:|--:|--:|")
        for feature, pair in sorted(feats.items()):
            if "on" in pair and "off" in pair:
                off, on = ms(pair["off"]), ms(pair["on"])
                w(f"| {feature} | {off:.2f} | {on:.2f} | {100 * (on / off - 1):+.1f}% |")
        w("")

    # ---- Skin ---------------------------------------------------------------------------------
    skins = sorted((name, row) for name, row in double.items() if name.startswith("BM_Skin/"))
    if skins:
        w("## Neighbour lists with a skin\n")
        w("`solver.neighbor_skin` on the reference 3D dam break from t = 0.25 s (the front running), 2 threads,")
        w("double: the fluid is re-sorted and the candidate lists (support + skin) rebuilt only when a particle")
        w("has moved half the skin; every step refines them to the pairs inside the support. *search* includes")
        w("that refinement.\n")
        w("| benchmark | ms/step | particle-steps/s | builds per step | search | B/particle |")
        w("|---|--:|--:|--:|--:|--:|")
        for name, row in skins:
            w(f"| {name} | {ms(row):.2f} | {mega(row['particle-steps/s'])} | {row['builds/step']:.2f} | "
              f"{fmt_share(row, 'f_nbr')} | {row['B/particle']:.0f} |")
        w("")

    # ---- Neighbour search ---------------------------------------------------------------------
    if neighbor:
        w("## Neighbour search variants (`neighbor_bench`, 2 threads, double)\n")
        w("| benchmark | ms | particles/s | per pair | grid B/particle |")
        w("|---|--:|--:|--:|--:|")
        for name, row in sorted(neighbor.items()):
            if "threads:2" not in name:
                continue
            pair = f"{row['pair_time'] * 1e9:.2f} ns" if "pair_time" in row else ""
            gb = f"{row['grid_B/particle']:.0f}" if "grid_B/particle" in row else ""
            w(f"| {name} | {ms(row):.3f} | {mega(row.get('particles/s', 0))} | {pair} | {gb} |")
        w("")

    # ---- Optimisations ----------------------------------------------------------------------
    spec = os.path.join(results_dir, "optimisations.json")
    if os.path.exists(spec):
        with open(spec) as f:
            changes = json.load(f)
        w("## What each optimisation bought\n")
        w("Before and after on the same machine and build flags, the fastest repetition of each (the least")
        w("disturbed on a shared machine); the listed files are in `bench/results/`.\n")
        w("| change | commit | benchmark | before | after | speed-up |")
        w("|---|---|---|--:|--:|--:|")
        for c in changes:
            before = load_best(os.path.join(results_dir, c["before"]))
            after = load_best(os.path.join(results_dir, c["after"]))
            for before_name, after_name in c["benchmarks"]:
                b, a = before.get(before_name), after.get(after_name)
                if b and a:
                    w(f"| {c['change']} | {c['commit']} | {after_name} | {b:.2f} ms | {a:.2f} ms | {b / a:.2f}× |")
        w("")

    for page in ("notes.md", "profiling.md"):  # hand-written analysis and the profiling how-to
        include(w, results_dir, page)

    with open(output, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
