#!/usr/bin/python3
"""Side-by-side figure of linear images (PFM) under one exposure, for README figures.

Usage: tools/caustics_figure.py OUT.png "TITLE=IMAGE.pfm" ... (/usr/bin/python3: numpy, matplotlib)

Every image is scaled so that the 99th percentile of the last one's luminance maps to white,
clipped and encoded with the sRGB curve, so the panels compare like for like.
"""
import sys

import matplotlib
import numpy as np
from measure_caustics import read_pfm

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

WHITE_PERCENTILE = 99.0


def encode_srgb(linear):
    c = np.clip(linear, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1.0 / 2.4) - 0.055)


def show_panel(ax, title, image):
    """One panel: `image` already scaled so that 1 is white."""
    ax.imshow(encode_srgb(image), interpolation="nearest")
    ax.set_title(title, fontsize=9)
    ax.axis("off")


def main():
    if len(sys.argv) < 3 or any("=" not in a for a in sys.argv[2:]):
        sys.exit(__doc__)
    panels = [a.split("=", 1) for a in sys.argv[2:]]
    images = [read_pfm(path)[::-1] for _, path in panels]  # PFM rows start at the bottom
    luminance = images[-1] @ np.array([0.2126, 0.7152, 0.0722])
    white = np.percentile(luminance[luminance > 0.0], WHITE_PERCENTILE)
    fig, axes = plt.subplots(1, len(images), figsize=(3.2 * len(images), 3.5))
    for ax, (title, _), image in zip(np.atleast_1d(axes), panels, images):
        show_panel(ax, title, image / white)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=100)


if __name__ == "__main__":
    main()
