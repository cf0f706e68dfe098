"""What the optional peers' Python scripts share (scripts/peers/*.py, run from this directory or
imported with it on sys.path): the accuracy runner's sample fractions and the all-or-nothing
write of a result file."""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import safe_output  # noqa: E402

INV_PHI = 0.6180339887498949  # 1 / golden ratio, as bench/harness/sweeps.hpp


def sample_fractions(n):
    """harness/sweeps.hpp sample_fractions: 0, 1 and frac(j / phi) in between, the same doubles."""
    return [0.0 if j == 0 else 1.0 if j + 1 == n else (j * INV_PHI) % 1.0 for j in range(n)]


def write_json(path, doc):
    """doc as indented JSON at path through scripts/safe_output.py: only a regular file or a new
    path is replaced, and an interrupted run never leaves a half-written file."""
    safe_output.write_text(path, json.dumps(doc, indent=1))
