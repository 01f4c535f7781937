"""examples/first_collision.py runs on real clips: it prints the first collision time that clearance()
gives and writes its PNG."""
import math
import os
import re
import subprocess
import sys

import mobb
from conftest import SOURCE_DIR


def test_first_collision_example(data, tmp_path):
    out = tmp_path / "first_collision.png"
    env = dict(os.environ, MOBB_DATA=data)
    p = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "examples", "first_collision.py"), "--out", str(out)],
                       capture_output=True, text=True, env=env, timeout=300)
    assert p.returncode == 0, p.stderr
    m = re.search(r"first collision: t = ([0-9.]+) s \(samples (\d+) of A, (\d+) of B\)", p.stdout)
    assert m, p.stdout
    with open(out, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    # the time is that of the first sample of A whose clearance is negative, under the example's placements
    a, b = mobb.load(os.path.join(data, "cmu", "002_01.bvh")), mobb.load(os.path.join(data, "cmu", "005_01.bvh"))
    c = mobb.clearance(a, (0, 0, 0, 0), b, (-1.5, -2.0, math.pi / 2, 0.5))
    first = int((c["gap"] < 0).argmax())
    assert float(m.group(1)) == round(float(c["t"][first]), 3)
    assert int(m.group(2)) == c["i"][first] and int(m.group(3)) == c["j"][first]
