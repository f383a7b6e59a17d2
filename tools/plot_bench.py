#!/usr/bin/env python3
"""Plots an `atrium bench` CSV: frame time against light count on log-log axes,
one line per mode (the median over views of each mode's median frame time);
with several --z-slicing schemes in the file, one line per clustered mode and scheme;
with several lighting stages, one line per mode and stage.

usage: tools/plot_bench.py BENCH.csv OUT.png [TITLE]
"""
import csv
import statistics
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main() -> int:
    if len(sys.argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    source, target = sys.argv[1], sys.argv[2]
    times = defaultdict(lambda: defaultdict(list))
    renderer, size = "", ""
    with open(source, newline="") as f:
        rows = list(csv.DictReader(f))
    several_slicings = len({row.get("z_slicing") for row in rows if row.get("z_slicing")}) > 1
    several_stages = len({row.get("lighting_stage") for row in rows if row.get("lighting_stage")}) > 1
    several_shadows = len({row.get("shadows") for row in rows if row.get("shadows")}) > 1
    for row in rows:
        if row.get("refused") or row["median_ms"] in ("", "-"):  # refused or skipped: no time
            continue
        label = row["mode"]
        if several_slicings and row.get("z_slicing"):
            label += "/" + row["z_slicing"]
        if several_stages and row.get("lighting_stage"):
            label += " (" + row["lighting_stage"] + ")"
        if several_shadows:
            label += f' {row["shadows"]} shadowed'
        times[label][int(row["lights"])].append(float(row["median_ms"]))
        renderer, size = row["renderer"], f'{row["width"]}x{row["height"]}'
    if not times:
        print(f"plot_bench: {source} has no rows", file=sys.stderr)
        return 1
    figure, axes = plt.subplots(figsize=(8, 5), dpi=100)
    # One colour per mode; with several lighting stages the compute stage's line is dashed.
    colours = {}
    for label, by_lights in times.items():
        mode = label.split(" (")[0]
        colour = colours.setdefault(mode, f"C{len(colours) % 10}" if len(colours) < 10 else plt.cm.tab20(len(colours) % 20))
        counts = sorted(by_lights)
        axes.plot(counts, [statistics.median(by_lights[c]) for c in counts], marker="o", label=label, color=colour,
                  linestyle="--" if label.endswith("(compute)") else "-")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("lights")
    axes.set_ylabel("frame time (ms, median)")
    title = sys.argv[3] if len(sys.argv) > 3 else f"Atrium, {size}, {renderer}"
    axes.set_title(title, fontsize=10)
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
