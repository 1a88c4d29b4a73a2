"""How often float32 rounding changes the answer of find_pairs at UTM-like
coordinates: the float64 answer (exact for the doubles) against
find_pairs(..., precision="float32") on the same array, for two families of
72,620 footprints 5 to 50 m across near (500000, 5712000), coordinates to the
millimetre: at random angles, and as axis-aligned neighbours that share an
edge or stand 1 mm apart. Prints (exact pairs, missed, false) per family.

    python3 python/bench/utm_float32_disagreement.py
"""

import numpy as np

import obbsat


def disagreement(poses):
    exact = {tuple(p) for p in obbsat.find_pairs(poses).tolist()}
    rounded = {tuple(p) for p in obbsat.find_pairs(poses, precision="float32").tolist()}
    return len(exact), len(exact - rounded), len(rounded - exact)


def main():
    rng = np.random.default_rng(1)
    n = 72620
    side = np.sqrt(n) * 30.0
    poses = np.empty((n, 6))
    poses[:, 0] = np.round(500000.0 + rng.uniform(0, side, n), 3)
    poses[:, 1] = np.round(5712000.0 + rng.uniform(0, side, n), 3)
    poses[:, 2:4] = np.round(rng.uniform(2.5, 25, (n, 2)), 3)
    angle = rng.uniform(0, 2 * np.pi, n)
    poses[:, 4], poses[:, 5] = np.cos(angle), np.sin(angle)
    print("random angles:", disagreement(poses))
    rows = poses.copy()
    rows[:, 4], rows[:, 5] = 1.0, 0.0
    gap = np.where(rng.uniform(size=n // 2) < 0.5, 0.0, 0.001)
    rows[1::2, 0] = rows[0::2, 0] + rows[0::2, 2] + rows[1::2, 2] + gap
    rows[1::2, 1] = rows[0::2, 1]
    print("edge-sharing neighbours:", disagreement(rows))


if __name__ == "__main__":
    main()
