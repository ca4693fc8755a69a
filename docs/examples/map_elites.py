#!/usr/bin/env python3
"""MAP-Elites over amorph's own operators, against amorph's crowding GA at the same budget.

An outer evolutionary loop written in Python (standard library only) over the ask/tell calls of
tools/python/amorph.py: a quality-diversity archive of body size x heading, each cell keeping
the furthest robot found with that size and travel direction, filled by mutating elites drawn at
random. The same number of evaluations through amorph.crowding(), amorph's own deterministic
crowding, gives the comparison: the furthest robot each found, and how many of the archive's
cells each one's evaluations reached.

Usage: map_elites.py [--lib PATH] [--evals N] [--seeds S] [--set KEY=VALUE ...]
Prints one line per seed and method, then the means (docs/embedding.md shows a run).
"""
import argparse
import math
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
import amorph  # noqa: E402

SIZE_BINS = 6      # voxels on a log scale: 1-3, 4-15, 16-63, 64-255, 256-1023, more
HEADING_BINS = 8   # the travel's direction, 45 degrees each


def cell_of(r):
    """the archive cell of a result: (size bin, heading bin), or None for a body with no score"""
    if r.diverged or r.fitness < 0 or r.voxels == 0:
        return None
    size = min(SIZE_BINS - 1, int(math.log(r.voxels, 4)))
    heading = int((math.atan2(r.dy, r.dx) + math.pi) / (2 * math.pi) * HEADING_BINS) % HEADING_BINS
    return size, heading


def map_elites(w, evals, seed, batch=20):
    """MAP-Elites: `batch` random genomes, then mutated elites until `evals` evaluations"""
    rng = random.Random(seed)
    w.seed(seed)
    archive = {}  # cell -> (fitness, genome)
    reached = set()
    done = 0

    def place(genome):
        nonlocal done
        r = w.evaluate(genome)
        done += 1
        c = cell_of(r)
        if c is None:
            return
        reached.add(c)
        if c not in archive or r.fitness > archive[c][0]:
            archive[c] = (r.fitness, genome)

    for _ in range(batch):
        place(w.new_genome())
    while done < evals:
        elites = sorted(archive)  # a fixed order: the draw below is the same on every platform
        if not elites:
            place(w.new_genome())
            continue
        a = archive[elites[rng.randrange(len(elites))]][1]
        b = archive[elites[rng.randrange(len(elites))]][1]
        child = w.offspring(a, b)[0] if rng.random() < 0.5 else w.mutate(a)
        place(child)
    best = max((f for f, _ in archive.values()), default=0.0)
    return best, len(reached)


def crowding(w, evals, seed, population=20):
    """amorph's deterministic crowding at the same budget; the cells its evaluations reached"""
    reached = set()
    best = [0.0]

    def measure(genome):
        r = w.evaluate(genome)
        c = cell_of(r)
        if c is not None:
            reached.add(c)
            best[0] = max(best[0], r.fitness)
        return r.score()

    amorph.crowding(w, population, evals // population - 1, seed, evaluate=measure)
    return best[0], len(reached)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lib", default=None)
    ap.add_argument("--evals", type=int, default=400)
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--set", action="append", default=["workspace=10"], metavar="KEY=VALUE")
    a = ap.parse_args()
    w = amorph.Workspace(dict(s.split("=", 1) for s in a.set), lib=a.lib)
    rows = {"map-elites": [], "crowding": []}
    for seed in range(1, a.seeds + 1):
        for name, fn in (("map-elites", map_elites), ("crowding", crowding)):
            best, cells = fn(w, a.evals, seed)
            rows[name].append((best, cells))
            print("seed %d %-10s best %.4f m, %d of %d cells reached" % (seed, name, best, cells, SIZE_BINS * HEADING_BINS))
            sys.stdout.flush()
    for name, v in rows.items():
        print("mean %-10s best %.4f m, %.1f cells" % (name, sum(b for b, _ in v) / len(v), sum(c for _, c in v) / len(v)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
