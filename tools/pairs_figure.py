#!/usr/bin/python3
"""Figure of scenes, ispm beside the path tracer, for README (two pairs to a row).

Usage: tools/pairs_figure.py OUT.png "SCENE=ISPM.pfm,REFERENCE.pfm" ...
(/usr/bin/python3: numpy, matplotlib)

Each pair is scaled so that the 99th percentile of its reference's luminance maps to white,
clipped and encoded with the sRGB curve: the two images of a scene compare like for like, and
scenes of different brightness each fill the range.
"""
import sys

import matplotlib
import numpy as np
from caustics_figure import WHITE_PERCENTILE, show_panel
from measure_caustics import read_pfm

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PAIRS_PER_ROW = 2


def parse(argument):
    scene, paths = argument.split("=", 1)
    ispm, reference = paths.split(",", 1)
    return scene, ispm, reference


def main():
    if len(sys.argv) < 3 or any("=" not in a or "," not in a for a in sys.argv[2:]):
        sys.exit(__doc__)
    pairs = [parse(a) for a in sys.argv[2:]]
    columns = 2 * min(len(pairs), PAIRS_PER_ROW)
    rows = (len(pairs) + PAIRS_PER_ROW - 1) // PAIRS_PER_ROW
    fig, axes = plt.subplots(rows, columns, figsize=(2.4 * columns, 2.7 * rows))
    axes = np.atleast_1d(axes).ravel()
    for ax in axes[2 * len(pairs):]:
        ax.axis("off")
    for i, (scene, ispm_path, reference_path) in enumerate(pairs):
        ispm = read_pfm(ispm_path)[::-1]  # PFM rows start at the bottom
        reference = read_pfm(reference_path)[::-1]
        luminance = reference @ np.array([0.2126, 0.7152, 0.0722])
        white = np.percentile(luminance[luminance > 0.0], WHITE_PERCENTILE)
        for ax, title, image in ((axes[2 * i], f"{scene}: ispm", ispm),
                                 (axes[2 * i + 1], "path tracer", reference)):
            show_panel(ax, title, image / white)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=100)


if __name__ == "__main__":
    main()
