#!/usr/bin/env python3
"""Turns `reconfig bench collision --json` into the Markdown table of docs/benchmarks.md.

    build/bin/reconfig bench collision --json > collision.json        # every scene (slow: scene 5)
    build/bin/reconfig bench collision --json --filter 'scene:[0-4]/' > collision.json
    bench/collision_table.py collision.json                             # prints the table

Times are real (wall-clock) times; ratios are baseline time / engine time (> 1: the engine is
faster), the engine being the 28-DOP full detection at 1 mm. "engine / FCL, CPU" compares the
two processes' CPU times over all threads instead, which steal time does not inflate.
The first table's FCL columns sample at the engine's ~33 proxy times (no guarantee between
samples); the third table holds the baselines that make the engine's promise: FCL discrete at
the step where no vertex moves more than the tolerance, and FCL's continuous collision per
proxy step, with what it misses of the engine's intervals.
"""
import json
import sys


def fmt_time(ns):
    if ns is None:
        return "—"
    for scale, unit in ((1e9, "s"), (1e6, "ms"), (1e3, "µs")):
        if ns >= scale:
            return f"{ns / scale:.3g} {unit}"
    return f"{ns:.3g} ns"


def fmt_ratio(r):
    if r is None:
        return "—"
    return f"{r:.3g}× faster" if r >= 1 else f"{1 / r:.3g}× slower"


def fmt_count(n):
    return f"{n / 1e6:.2f} M" if n >= 1e6 else f"{n / 1e3:.1f} K" if n >= 1e3 else f"{n:.0f}"


def main(path):
    report = json.load(open(path))
    context = report["context"]
    load = context.get("load_avg") or [None]
    print(f"<!-- {context.get('date', '')}, {context.get('num_cpus', '?')} CPUs, "
          f"load average {'?' if load[0] is None else f'{load[0]:.2f}'} at the start -->")
    print("| # | scene | triangles | parts | samples | engine 28-DOP | 8-DOP | 80-DOP | every contact | update after one key edit "
          "| reference | FCL 0.7 at the proxy times (no guarantee) | FCL 0.7 at the proxy times, all contacts "
          "| engine / reference | engine / FCL at the proxy times | engine / FCL at the proxy times, CPU "
          "| engine / FCL at the proxy times, all contacts | FCL colliding samples (missed by engine) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for row in report["summary"]:
        fcl_hits = row.get("fcl_colliding_samples")
        hits = "—" if fcl_hits is None else f"{fcl_hits:.0f} ({row.get('fcl_missed_by_engine', 0):.0f})"
        print(f"| {row['scene']} | {row['label']} | {fmt_count(row['triangles'])} | {row['parts']:.0f} "
              f"| {row['samples']:.0f} | {fmt_time(row['engine_ns'])} | {fmt_time(row['dop8_ns'])} "
              f"| {fmt_time(row['dop80_ns'])} | {fmt_time(row.get('all_contacts_ns'))} | {fmt_time(row['update_ns'])} | {fmt_time(row['reference_ns'])} "
              f"| {fmt_time(row['fcl_ns'])} | {fmt_time(row.get('fcl_all_contacts_ns'))} "
              f"| {fmt_ratio(row['engine_vs_reference'])} | {fmt_ratio(row['engine_vs_fcl'])} "
              f"| {fmt_ratio(row.get('engine_vs_fcl_cpu'))} "
              f"| {fmt_ratio(row.get('engine_vs_fcl_all_contacts'))} | {hits} |")


def dop_work(report):
    """Work counts of the full detection per DOP family: bound tests / narrow-phase tests (these
    do not depend on the machine's load)."""
    work = {}
    for b in report["benchmarks"]:
        parts = b["name"].split("/")
        if parts[0] != "BM_FullDetection":
            continue
        fields = dict(p.split(":", 1) for p in parts[1:] if ":" in p)
        which = "all" if fields.get("all") == "1" else fields.get("dop", "28")
        work.setdefault(fields["scene"], {})[which] = (b.get("bound_tests"), b.get("narrow_phase"), b.get("contacts"))
    print()
    print("| # | 28-DOP: bound tests / narrow-phase tests | 8-DOP | 80-DOP | 28-DOP, every contact | contacts found "
          "(every contact) |")
    print("|---|---|---|---|---|---|")
    for scene, by_dop in work.items():
        cells = []
        for dop in ("28", "8", "80", "all"):
            w = by_dop.get(dop)
            cells.append("—" if w is None else f"{w[0]:,.0f} / {w[1]:,.0f}")
        found = by_dop.get("28", (None, None, None))[2]
        every = by_dop.get("all", (None, None, None))[2]
        count = "—" if found is None else f"{found:,.0f}" + ("" if every is None else f" ({every:,.0f})")
        print(f"| {scene} | {' | '.join(cells)} | {count} |")


def honest_baselines(report):
    """FCL at the same guarantee and FCL's continuous collision, per scene."""
    rows = [r for r in report["summary"] if r.get("fcl_guaranteed_ns") is not None or r.get("fcl_ccd_ns") is not None]
    if not rows:
        return
    print()
    print("| # | engine 28-DOP | FCL samples at the guarantee (colliding) | FCL at the guarantee | FCL at the guarantee, all contacts "
          "| engine / FCL | engine / FCL, CPU | engine / FCL all contacts | FCL CCD (pair-steps) | engine / FCL CCD "
          "| engine / FCL CCD, CPU | engine intervals | CCD: starts not given | CCD: intervals without contact "
          "| CCD: ends not given | CCD: contacts outside the engine's | CCD: largest first-contact difference |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")

    def count(row, key):
        return "—" if row.get(key) is None else f"{row[key]:,.0f}"

    for row in rows:
        samples = "—" if row.get("fcl_guaranteed_samples") is None else \
            f"{row['fcl_guaranteed_samples']:,.0f} ({row.get('fcl_guaranteed_colliding_samples', 0):,.0f})"
        error = row.get("ccd_first_contact_error")
        print(f"| {row['scene']} | {fmt_time(row['engine_ns'])} | {samples} | {fmt_time(row.get('fcl_guaranteed_ns'))} "
              f"| {fmt_time(row.get('fcl_guaranteed_all_contacts_ns'))} | {fmt_ratio(row.get('engine_vs_fcl_guaranteed'))} "
              f"| {fmt_ratio(row.get('engine_vs_fcl_guaranteed_cpu'))} "
              f"| {fmt_ratio(row.get('engine_vs_fcl_guaranteed_all_contacts'))} "
              f"| {fmt_time(row.get('fcl_ccd_ns'))} ({count(row, 'ccd_pair_steps')}) | {fmt_ratio(row.get('engine_vs_fcl_ccd'))} "
              f"| {fmt_ratio(row.get('engine_vs_fcl_ccd_cpu'))} | {count(row, 'ccd_engine_intervals')} "
              f"| {count(row, 'ccd_starts_missed')} | {count(row, 'ccd_intervals_missed')} | {count(row, 'ccd_ends_unreported')} "
              f"| {count(row, 'ccd_extra_contacts')} | {'—' if error is None else f'{error:.2g}'} |")


if __name__ == "__main__":
    path = sys.argv[1] if len(sys.argv) > 1 else "/dev/stdin"
    main(path)
    dop_work(json.load(open(path)))
    honest_baselines(json.load(open(path)))
