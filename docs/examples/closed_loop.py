#!/usr/bin/env python3
"""A closed-loop controller for a shipped robot, tuned by a (1+1) evolution strategy, against the
robot's own open-loop sinusoid over 30 cycles (docs/embedding.md, Stepping).

The robot is a run folder's best (default: results/representations/gmx-1, the seed's GMX run),
in that run's settings. Its actuated voxels (those whose sinusoid moves their scale) are driven
every EVERY steps by phase oscillators: voxel i's scale is 1 + amp sin(w t + phi_i), amp and w
the sinusoid's own, with phi_i = th0 x_i + th1 y_i (a travelling wave across the body, x and y
the voxel's place at the settle in body lengths) + th2 c_i + th3 c_i (x_i + y_i), c_i = 1 while
the voxel touches the floor (the feedback: a contact shifts the voxel's oscillator, by how much
depending on where it is). The passive voxels keep theirs. theta = 0 is every actuated voxel in phase,
as the open loop; the strategy keeps a step of the four values when the robot then travels
further over 30 cycles (the centre of mass's horizontal displacement from the settle).

Usage: closed_loop.py [--lib PATH] [--run DIR] [--iters N] [--every K] [--seed S]
"""
import argparse
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "python"))
import amorph  # noqa: E402

RUN_KEYS = {"population", "evaluations", "seed", "threads", "checkpoint_seconds"}


def settings_of(run):
    """a run folder's config.txt as settings (the keys of one robot)"""
    out = {}
    for line in open(os.path.join(run, "config.txt")):
        line = line.split("#")[0].strip()
        if "=" in line:
            k, v = (x.strip() for x in line.split("=", 1))
            if k not in RUN_KEYS:
                out[k] = v
    return out


def travel(o0, o1):
    return math.hypot(o1["com"][0] - o0["com"][0], o1["com"][1] - o0["com"][1])


class Controller:
    def __init__(self, sim, text, cycles, every):
        self.sim, self.text, self.every = sim, text, every
        o = sim.reset(text)
        self.period = sim.settled.period_steps
        self.steps = cycles * self.period
        # the sinusoid's own: which voxels it moves, how far, and its frequency per step
        amp, active = 0.0, [False] * sim.nv
        for k in range(self.period):
            sc, rt = sim.sinusoid()
            for i in range(sim.nv):
                if sc[i] != 1.0 or rt[i] != 0.0:
                    active[i] = True
                    amp = max(amp, abs(sc[i] - 1.0))
            sim.step(None, 1)
        self.amp, self.active = amp, [i for i in range(sim.nv) if active[i]]
        self.dw = 2 * math.pi / self.period
        # each voxel's place at the settle, in body lengths from the centre of mass
        pos, com = o["pos"], o["com"]
        span = max(max(p[0] for p in pos) - min(p[0] for p in pos), max(p[1] for p in pos) - min(p[1] for p in pos), 1e-9)
        self.xy = [((pos[i][0] - com[0]) / span, (pos[i][1] - com[1]) / span) for i in range(sim.nv)]

    def run(self, theta):
        """the travel over the cycles under theta (None: the open-loop sinusoid)"""
        sim = self.sim
        o0 = o = sim.reset(self.text)
        action = [math.nan] * sim.nv
        for t in range(0, self.steps, self.every):
            if theta is None:
                o = sim.step(None, self.every)
                continue
            contact = o["contact"]
            for i in self.active:
                x, y = self.xy[i]
                c = 1.0 if contact[i] else 0.0
                action[i] = 1.0 + self.amp * math.sin(self.dw * t + theta[0] * x + theta[1] * y + theta[2] * c + theta[3] * c * (x + y))
            o = sim.step(action, self.every)
        return travel(o0, o) if not o["diverged"] else 0.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lib", default=None)
    ap.add_argument("--run", default=os.path.join(HERE, "..", "..", "results", "representations", "gmx-1"))
    ap.add_argument("--cycles", type=int, default=30)
    ap.add_argument("--iters", type=int, default=30)
    ap.add_argument("--every", type=int, default=10)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    s = settings_of(a.run)
    s["cycles"] = str(a.cycles)
    sim = amorph.Sim(s, lib=a.lib)
    text = open(os.path.join(a.run, "best.genome")).read()
    r = sim.w.evaluate(text)
    ctl = Controller(sim, text, a.cycles, a.every)
    body = ctl.sim.observe()
    print("robot %s: %d voxels, %d actuated, sinusoid amplitude %.4f" % (a.run, sim.nv, len(ctl.active), ctl.amp))
    print("open loop (amorph sim --cycles %d): %.4f m" % (a.cycles, r.travel))
    print("open loop, stepped every %d steps: %.4f m" % (a.every, ctl.run(None)))
    rng = random.Random(a.seed)
    theta, best, sigma = [0.0] * 4, ctl.run([0.0] * 4), 1.0
    print("controller theta = 0: %.4f m" % best)
    for it in range(a.iters):
        cand = [v + rng.gauss(0, sigma) for v in theta]
        f = ctl.run(cand)
        if f > best:
            theta, best, sigma = cand, f, sigma * 1.5
        else:
            sigma *= 0.85
        print("iteration %d: %.4f m (best %.4f, sigma %.2f)" % (it + 1, f, best, sigma))
        sys.stdout.flush()
    print("tuned controller: %.4f m over %d cycles, %.2fx the open loop; theta %s" %
          (best, a.cycles, best / r.travel if r.travel > 0 else float("inf"), " ".join("%.3f" % v for v in theta)))
    del body
    return 0


if __name__ == "__main__":
    sys.exit(main())
