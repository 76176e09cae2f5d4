#!/usr/bin/python3
# Draws a `ispm bench --sweep` CSV as error against time per frame (log-log): the ispm
# configurations labelled by photon count, a colour and marker per combination of swept modes
# (radius_mode, splat_mode, ...; shadows, splat_resolution and edge_samples as fill, size and
# edge width), with their Pareto front, and the path tracer's curve.
# Usage: tools/plot_bench.py CSV OUT.png [--title T]   (Debian's matplotlib: /usr/bin/python3)
import argparse
import sys

import matplotlib
from csv_input import fail
from csv_input import read_rows as read_csv_rows

matplotlib.use("Agg")  # headless: no display on the test machine
import matplotlib.pyplot as plt  # noqa: E402

FIGURE_SIZE_IN = (10.0, 5.0)  # room right of the axes for the legend
DPI = 120
LABEL_OFFSET_PT = (5, 4)  # photon-count labels sit just above and right of their point
REQUIRED_COLUMNS = ("kind", "spp", "photons", "total_ms", "relmse_total")
# Choice settings a sweep may vary: each combination of their values is a series of its own.
MODE_COLUMNS = ("radius_mode", "splat_mode", "splat_shape", "splat_resolution", "radius_scale",
                "importance", "widen_strong", "shadows", "edge_samples")
# Modes drawn by a marker's look instead of its colour, so that the colours stay few: points that
# differ only in them share colour and marker. Fill: the first value filled, the others hollow.
FILL_COLUMN = "shadows"
# Size: the first value largest (the splat buffer's resolution: 1, 1/2, 1/4 shrink the markers as
# they shrink the buffer).
SIZE_COLUMN = "splat_resolution"
MARKER_SIZES_PT2 = (56, 26, 10)
# Edge width: the first value thin, the others thick (edge samples off, then on).
WIDTH_COLUMN = "edge_samples"
EDGE_WIDTHS_PT = (0.8, 2.2)
SERIES_COLOURS = ("tab:blue", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:cyan",
                  "tab:olive", "tab:pink")
SERIES_MARKERS = ("o", "^", "s", "D", "v", "P", "X", "*")


def read_rows(path):
    rows = read_csv_rows(path, REQUIRED_COLUMNS, "an `ispm bench --sweep` CSV")
    ispm = [r for r in rows if r["kind"] == "ispm"]
    reference = [r for r in rows if r["kind"] == "reference"]
    if not ispm and not reference:
        fail(f"{path}: no ispm or reference rows")
    return ispm, reference


def series_marker(i):
    """Marker of series i: with more series than colours, a series that repeats a colour takes
    the next marker, so that no two series look alike."""
    return (i + i // len(SERIES_COLOURS)) % len(SERIES_MARKERS)


def compute_pareto_front(points):
    """Points no other point beats in both time and error, sorted by time."""
    front = []
    best_error = float("inf")
    for time_ms, error, label in sorted(points):
        if error < best_error:
            front.append((time_ms, error, label))
            best_error = error
    return front


def main():
    parser = argparse.ArgumentParser(
        description="Draw an `ispm bench --sweep` CSV: relMSE against time per frame.")
    parser.add_argument("csv", help="CSV written by `ispm bench --sweep ... --csv`")
    parser.add_argument("out", help="output PNG")
    parser.add_argument("--title", default="Speed against accuracy", help="chart title")
    args = parser.parse_args()

    ispm, reference = read_rows(args.csv)
    fig, ax = plt.subplots(figsize=FIGURE_SIZE_IN)

    if reference:
        curve = sorted((float(r["total_ms"]), float(r["relmse_total"]), int(r["spp"]))
                       for r in reference)
        ax.plot([c[0] for c in curve], [c[1] for c in curve], "s-", color="tab:grey",
                label="path tracer (cumulative time, 1, 2, 4, ... spp)")
        for time_ms, error, spp in curve:
            ax.annotate(f"{spp} spp", (time_ms, error), textcoords="offset points",
                        xytext=LABEL_OFFSET_PT, fontsize=7, color="tab:grey")

    if ispm:
        points = [(float(r["total_ms"]), float(r["relmse_total"]), r["photons"]) for r in ispm]
        # Colour and marker per style (the swept modes but the channel columns), the channel
        # columns as fill, size and edge width; photon counts as labels.
        modes = [c for c in MODE_COLUMNS if c in ispm[0] and len({r[c] for r in ispm}) > 1]
        channels = [c for c in (FILL_COLUMN, SIZE_COLUMN, WIDTH_COLUMN) if c in modes]
        styles = {}                         # style -> index
        values = {c: [] for c in channels}  # each channel column's values, first seen first
        groups = {}
        for r, point in zip(ispm, points):
            style = " ".join(f"{c}={r[c]}" for c in modes if c not in channels)
            styles.setdefault(style, len(styles))
            for c in channels:
                if r[c] not in values[c]:
                    values[c].append(r[c])
            key = (style,) + tuple(r[c] for c in channels)
            groups.setdefault(key, []).append(point)

        def channel_index(column, key):
            return values[column].index(key[1 + channels.index(column)]) if column in channels else 0

        for key, group in groups.items():
            i = styles[key[0]]
            colour = SERIES_COLOURS[i % len(SERIES_COLOURS)]
            marker = SERIES_MARKERS[series_marker(i)]
            filled = channel_index(FILL_COLUMN, key) == 0
            area = MARKER_SIZES_PT2[min(channel_index(SIZE_COLUMN, key), len(MARKER_SIZES_PT2) - 1)]
            width = EDGE_WIDTHS_PT[min(channel_index(WIDTH_COLUMN, key), len(EDGE_WIDTHS_PT) - 1)]
            ax.scatter([p[0] for p in group], [p[1] for p in group], zorder=3, s=area,
                       marker=marker, linewidths=width,
                       facecolors=colour if filled else "none", edgecolors=colour)
            for time_ms, error, photons in group:
                ax.annotate(f"{int(float(photons)):,}", (time_ms, error),
                            textcoords="offset points", xytext=LABEL_OFFSET_PT, fontsize=5,
                            color=colour)
        # The legend names each style once, then what each channel's looks mean.
        for style, i in styles.items():
            ax.scatter([], [], marker=SERIES_MARKERS[series_marker(i)],
                       color=SERIES_COLOURS[i % len(SERIES_COLOURS)],
                       label=f"{style or 'ispm configurations'} (median frame time)")
        for c in channels:
            for k, value in enumerate(values[c]):
                look = {FILL_COLUMN: "filled" if k == 0 else "hollow",
                        SIZE_COLUMN: ("large", "medium", "small")[min(k, 2)],
                        WIDTH_COLUMN: "thin edge" if k == 0 else "thick edge"}[c]
                # Width entries hollow, so that the edge shows.
                solid = (c == SIZE_COLUMN) or (c == FILL_COLUMN and k == 0)
                ax.scatter([], [], marker="o", color="tab:grey",
                           facecolors="tab:grey" if solid else "none",
                           s=MARKER_SIZES_PT2[min(k, 2)] if c == SIZE_COLUMN else 26,
                           linewidths=EDGE_WIDTHS_PT[min(k, 1)] if c == WIDTH_COLUMN else 1.0,
                           label=f"{c}={value}: {look}")
        front = compute_pareto_front(points)
        ax.plot([p[0] for p in front], [p[1] for p in front], "-", color="tab:orange", zorder=2,
                label="ispm Pareto front")

    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per frame (ms; path tracer: cumulative time of its samples)")
    ax.set_ylabel("relMSE of total radiance against the reference")
    ax.set_title(args.title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    try:
        fig.savefig(args.out, dpi=DPI)
    except OSError as e:
        fail(f"{args.out}: {e.strerror}")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
