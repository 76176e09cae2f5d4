#!/usr/bin/python3
# Draws tools/converge.sh's CSV as rel RMSE (4x4) of the indirect light against accumulated frames
# (log-log), one line per scene, with the 1/sqrt(frames) of pure noise from each first frame.
# Usage: tools/plot_converge.py CSV OUT.png   (Debian's matplotlib: /usr/bin/python3)
import sys

import matplotlib
from csv_input import fail, read_rows

matplotlib.use("Agg")  # headless: no display on the test machine
import matplotlib.pyplot as plt  # noqa: E402

FIGURE_SIZE_IN = (7.0, 5.0)
DPI = 120
REQUIRED_COLUMNS = ("label", "frames", "energy", "rel_rmse4")


def read_series(path):
    rows = read_rows(path, REQUIRED_COLUMNS, "a tools/converge.sh CSV")
    series = {}
    for i, r in enumerate(rows, start=2):
        try:
            point = (int(r["frames"]), float(r["rel_rmse4"]))
        except ValueError:
            fail(f"{path}: line {i}: expected a whole number of frames and a number for rel_rmse4")
        series.setdefault(r["label"], []).append(point)
    if not series:
        fail(f"{path}: no rows")
    return series


def main():
    if len(sys.argv) != 3:
        fail("usage: tools/plot_converge.py CSV OUT.png")
    series = read_series(sys.argv[1])
    fig, ax = plt.subplots(figsize=FIGURE_SIZE_IN)
    for label, points in series.items():
        points.sort()
        frames = [p[0] for p in points]
        errors = [p[1] for p in points]
        line = ax.plot(frames, errors, marker="o", label=label)[0]
        first_frames, first_error = points[0]
        noise = [first_error * (first_frames / f) ** 0.5 for f in frames]
        ax.plot(frames, noise, linestyle=":", color=line.get_color())
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("accumulated frames (50,000 photons each)")
    ax.set_ylabel("rel RMSE (4x4) of the indirect light")
    ax.set_title("Error against accumulated frames (dotted: 1/sqrt(frames), noise alone)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=DPI)


if __name__ == "__main__":
    main()
