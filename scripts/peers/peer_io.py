"""What the optional peers' Python scripts share (scripts/peers/*.py, run from this directory or
imported with it on sys.path): the accuracy runner's sample fractions and the all-or-nothing
write of a result file."""
import json
import os

INV_PHI = 0.6180339887498949  # 1 / golden ratio, as bench/harness/sweeps.hpp


def sample_fractions(n):
    """harness/sweeps.hpp sample_fractions: 0, 1 and frac(j / phi) in between, the same doubles."""
    return [0.0 if j == 0 else 1.0 if j + 1 == n else (j * INV_PHI) % 1.0 for j in range(n)]


def write_json(path, doc):
    """doc as indented JSON at path, written under a temporary name and renamed: an interrupted
    run never leaves a half-written file."""
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(doc, f, indent=1)
    os.replace(tmp, path)
