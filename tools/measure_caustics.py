#!/usr/bin/python3
# Quality figures of an image in its caustic region: the 4x4-pixel blocks where the light-traced
# reference holds more than the path-traced one (which cannot see caustics from point, spot or
# sun lights) by over half the light reference's mean, and over the whole image (the energy and
# rel RMSE 4x4 of docs/design.md "Measuring quality", luminance-free: all channels together).
# Usage: tools/measure_caustics.py IMAGE.pfm LIGHT_REF.pfm PATH_REF.pfm  (/usr/bin/python3: numpy)
import sys

import numpy as np

BLOCK_PX = 4  # rel RMSE blocks (docs/design.md "Measuring quality")
CAUSTIC_SHARE = 0.5  # caustic light above this fraction of the reference's mean radiance


def read_pfm(path):
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            sys.exit(f"{path}: expected a colour PFM")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        dtype = "<f4" if scale < 0 else ">f4"
        data = np.frombuffer(f.read(), dtype=dtype).reshape(height, width, 3)
    return data.astype(np.float64)


def to_blocks(image):
    h, w, _ = image.shape
    h, w = h // BLOCK_PX * BLOCK_PX, w // BLOCK_PX * BLOCK_PX
    return image[:h, :w].reshape(h // BLOCK_PX, BLOCK_PX, w // BLOCK_PX, BLOCK_PX, 3).mean(axis=(1, 3))


def report(name, test, ref, mask):
    energy = test[mask].mean() / ref[mask].mean()
    rel_rmse = np.sqrt(((test[mask] - ref[mask]) ** 2).mean()) / ref[mask].mean()
    print(f"{name}: {mask.sum()} blocks, energy {energy:.3f}, rel RMSE (4x4) {rel_rmse:.3f}")


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__ or "usage: measure_caustics.py IMAGE LIGHT_REF PATH_REF")
    image, light, path = (to_blocks(read_pfm(p)) for p in sys.argv[1:4])
    if not (image.shape == light.shape == path.shape):
        sys.exit("the three images must have one size")
    caustic = light.mean(axis=2) - path.mean(axis=2)
    report("caustic region", image, light, caustic > CAUSTIC_SHARE * light.mean())
    report("whole image", image, light, light.mean(axis=2) > 0.0)


if __name__ == "__main__":
    main()
