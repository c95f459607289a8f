#!/usr/bin/env python3
"""Interleaved CPU-time A/B of two lancer binaries on POV-Ray sample scenes (a benchmark, not a test).

Why it exists: callgrind's instruction counts judge most speed changes on this shared machine,
but they count a 256-bit operation or a gather as one instruction, and twice (walk23's AVX
walks, noise24's AVX2 gathers) the count fell while the clock rose. Timings on a loaded
machine drift by tens of percent over minutes, so the two binaries run alternately, round after
round, and the medians of their CPU times (user + system of the child, which waiting for a core
does not inflate) are compared.

usage: scripts/ab_time.py [-r ROUNDS] [-W 320] [-H 240] BASE_BIN NEW_BIN scene...
  scene: a path under /usr/share/povray-3.7/scenes without .pov (e.g. objects/superel1),
         or a .pov file path. Each scene runs in a temporary copy of its directory.
Prints per scene: best and median CPU seconds of each binary and NEW/BASE for both, then the
geometric mean of the median ratios.
"""

import argparse
import math
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile

SAMPLES = "/usr/share/povray-3.7/scenes"


def cpu_of(cmd, cwd, env):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-r", "--rounds", type=int, default=9)
    ap.add_argument("-W", type=int, default=320)
    ap.add_argument("-H", type=int, default=240)
    ap.add_argument("base")
    ap.add_argument("new")
    ap.add_argument("scenes", nargs="+")
    a = ap.parse_args()
    # lancer reads no povray.ini/povray.conf, so the result does not depend on the machine.
    env = dict(os.environ, LANCER_NO_CONFIG="1")
    bins = [os.path.abspath(a.base), os.path.abspath(a.new)]
    ratios = []
    for scene in a.scenes:
        path = scene if scene.endswith(".pov") else os.path.join(SAMPLES, scene + ".pov")
        work = tempfile.mkdtemp(prefix="ab_time.")
        try:
            shutil.copytree(os.path.dirname(os.path.abspath(path)), work, dirs_exist_ok=True)
            cmd = [os.path.basename(path), f"-W{a.W}", f"-H{a.H}", "-A", "+WT1", "-GA", "+FP", "-O/dev/null"]
            times = [[], []]
            for _ in range(a.rounds):
                for i, b in enumerate(bins):
                    times[i].append(cpu_of([b] + cmd, work, env))
        finally:
            shutil.rmtree(work)
        t0, t1 = times
        med = statistics.median(t1) / statistics.median(t0)
        ratios.append(med)
        print(
            f"{scene}: base best {min(t0):.4f} med {statistics.median(t0):.4f} | "
            f"new best {min(t1):.4f} med {statistics.median(t1):.4f} | "
            f"new/base best {min(t1) / min(t0):.3f} med {med:.3f}",
            flush=True,
        )
    if len(ratios) > 1:
        geo = math.exp(sum(math.log(r) for r in ratios) / len(ratios))
        print(f"geometric mean of the median ratios over {len(ratios)} scenes: {geo:.3f}")


if __name__ == "__main__":
    sys.exit(main())
