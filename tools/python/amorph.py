"""amorph from Python: evaluate robots and run amorph's genetic operators through libamorph.so.

Standard library only (ctypes); numpy is never needed. docs/embedding.md is the manual.

    import amorph
    w = amorph.Workspace({"cycles": 4})           # the embedding API's workspace, with settings
    r = w.evaluate(open("robot.genome").read())    # a genome or lattice text: an amorph.Result
    print(r.fitness, "%016x" % r.hash)
    w = amorph.Workspace.from_run("runs/dct")      # a run folder's settings (its config.txt)

Ask/tell, amorph's own operators with any outer loop:

    w.seed(5)
    pop = [w.new_genome() for _ in range(20)]
    a, b = w.offspring(pop[0], pop[1])             # crossover, then each mutated, as a run breeds
    d = w.distance(a, pop[0])                      # the crowding distance of their bodies
    meets, replaces = w.crowd(pop[0], fa, pop[1], fb, a, f1, b, f2)

crowding(w, population, generations, seed) is amorph's own run (deterministic crowding) written
over these calls: it ends in the population `amorph evolve` reaches with the same settings.

The library is found, in order: the path given to Workspace or load(), $AMORPH_LIB, beside this
file, the checkout's build/ folder (this file is tools/python/amorph.py), then the system's
(ctypes.util.find_library("amorph"), after `make install`).
"""
import ctypes
import ctypes.util
import math
import os

__all__ = ["Result", "Workspace", "Sim", "AmorphError", "load", "crowding"]

GENOME_TEXT_MAX = 1 << 22  # bytes a genome text may take (the library's AM_GENOME_TEXT_MAX is below it)


class AmorphError(Exception):
    """a refusal of the library: its one-line message"""


class Result(ctypes.Structure):
    """am_result (include/amorph/sim.h), field by field; am_api_result_size() checks the layout"""
    _fields_ = [
        ("fitness", ctypes.c_double), ("travel", ctypes.c_double),
        ("dx", ctypes.c_double), ("dy", ctypes.c_double), ("dz", ctypes.c_double),
        ("sustained", ctypes.c_double),
        ("voxels", ctypes.c_int), ("links", ctypes.c_int),
        ("dt", ctypes.c_double), ("period_steps", ctypes.c_int),
        ("relax_steps", ctypes.c_long), ("move_steps", ctypes.c_long), ("steps", ctypes.c_long),
        ("relax_dt", ctypes.c_double), ("relax_retried", ctypes.c_int),
        ("diverged", ctypes.c_int), ("settled", ctypes.c_int),
        ("residual_speed", ctypes.c_double), ("kinetic_resets", ctypes.c_long),
        ("sim_seconds", ctypes.c_double), ("rebuilds", ctypes.c_long),
        ("max_pairs", ctypes.c_int), ("hash", ctypes.c_uint64),
    ]

    def score(self):
        """the fitness as crowding compares it: NaN for a diverged body (it always loses)"""
        return math.nan if self.diverged else self.fitness


_API_VERSION = 4  # the functions below are AM_API_VERSION 4's


class Obs(ctypes.Structure):
    """am_obs (include/amorph/sim.h)"""
    _fields_ = [("step", ctypes.c_long), ("time", ctypes.c_double), ("com", ctypes.c_double * 3), ("com_vel", ctypes.c_double * 3),
                ("nv", ctypes.c_int), ("contacts", ctypes.c_int), ("diverged", ctypes.c_int), ("hash", ctypes.c_uint64)]
_libs = {}


def _candidates(path):
    if path:
        return [path]
    out = []
    if os.environ.get("AMORPH_LIB"):
        out.append(os.environ["AMORPH_LIB"])
    here = os.path.dirname(os.path.abspath(__file__))
    out += [os.path.join(here, "libamorph.so"), os.path.join(here, "libamorph.so.1"),
            os.path.join(here, "..", "..", "build", "libamorph.so")]
    found = ctypes.util.find_library("amorph")
    if found:
        out.append(found)
    return out


def load(path=None):
    """the library (a ctypes.CDLL with its functions typed), found as the module's doc says"""
    tried = []
    for cand in _candidates(path):
        if cand in _libs:
            return _libs[cand]
        if os.path.sep in cand and not os.path.exists(cand):
            tried.append(cand)
            continue
        try:
            lib = ctypes.CDLL(cand)
        except OSError as e:
            tried.append("%s (%s)" % (cand, e))
            continue
        _type(lib, cand)
        _libs[cand] = lib
        return lib
    raise AmorphError("libamorph not found (make shared, or set AMORPH_LIB); tried: " + ", ".join(tried))


def _type(lib, where):
    c_int, c_long, c_char_p, c_double, P = ctypes.c_int, ctypes.c_long, ctypes.c_char_p, ctypes.c_double, ctypes.c_void_p
    sig = {
        "am_api_version": ([], c_int),
        "am_api_work_size": ([], c_long),
        "am_api_result_size": ([], c_long),
        "am_api_init": ([P, c_long, c_char_p, c_int], c_int),
        "am_api_set": ([P, c_char_p, c_char_p, c_char_p, c_int], c_int),
        "am_api_set_config": ([P, c_char_p, c_char_p, c_char_p, c_int], c_int),
        "am_api_eval_genome": ([P, c_char_p, ctypes.POINTER(Result), c_char_p, c_int], c_int),
        "am_api_eval_lattice": ([P, c_char_p, ctypes.POINTER(Result), c_char_p, c_int], c_int),
        "am_api_eval_vxa": ([P, c_char_p, ctypes.POINTER(Result), c_char_p, c_int], c_int),
        "am_api_seed": ([P, c_long, c_char_p, c_int], c_int),
        "am_api_genome_new": ([P, c_char_p, c_long, c_char_p, c_int], c_int),
        "am_api_pairing": ([P, c_int, ctypes.POINTER(c_int), c_char_p, c_int], c_int),
        "am_api_offspring": ([P, c_char_p, c_char_p, c_char_p, c_char_p, c_long, c_char_p, c_int], c_int),
        "am_api_mutate": ([P, c_char_p, c_char_p, c_long, c_char_p, c_int], c_int),
        "am_api_distance": ([P, c_char_p, c_char_p, ctypes.POINTER(c_double), c_char_p, c_int], c_int),
        "am_api_crowd": ([P, c_char_p, c_double, c_char_p, c_double, c_char_p, c_double, c_char_p, c_double,
                          ctypes.POINTER(c_int), ctypes.POINTER(c_int), c_char_p, c_int], c_int),
        "am_api_sim_open": ([P, c_char_p, c_char_p, c_int], c_int),
        "am_api_sim_settle": ([P, ctypes.POINTER(Result), c_char_p, c_int], c_int),
        "am_api_sim_voxels": ([P, P, P], c_long),
        "am_api_sim_step": ([P, c_long, P, P, c_char_p, c_int], c_int),
        "am_api_sim_sinusoid": ([P, P, P, c_char_p, c_int], c_int),
        "am_api_sim_observe": ([P, ctypes.POINTER(Obs), P, P, P, P, c_char_p, c_int], c_int),
    }
    for name, (args, res) in sig.items():
        try:
            fn = getattr(lib, name)
        except AttributeError:
            raise AmorphError("%s has no %s: a library older than this module (API %d)" % (where, name, _API_VERSION))
        fn.argtypes, fn.restype = args, res
    if lib.am_api_version() < _API_VERSION:
        raise AmorphError("%s is API %d; this module needs %d" % (where, lib.am_api_version(), _API_VERSION))
    if lib.am_api_result_size() != ctypes.sizeof(Result):
        raise AmorphError("am_result is %d bytes in %s, %d here" % (lib.am_api_result_size(), where, ctypes.sizeof(Result)))


class Workspace:
    """one workspace of the embedding API: settings, evaluations and the genome operators' random
    stream. Calls on one workspace are sequential; use one workspace per thread."""

    def __init__(self, settings=None, lib=None):
        self.lib = load(lib)
        size = self.lib.am_api_work_size()
        self.work = ctypes.create_string_buffer(size)  # malloc'd: aligned for a double
        self.err = ctypes.create_string_buffer(512)
        self._out = [ctypes.create_string_buffer(GENOME_TEXT_MAX) for _ in range(2)]
        self._check(self.lib.am_api_init(self.work, size, self.err, len(self.err)))
        for key, value in (settings or {}).items():
            self.set(key, value)

    def _check(self, status):
        if status != 0:
            raise AmorphError(self.err.value.decode())

    def set(self, key, value):
        """one configuration key (amorph evolve --help-config), as `amorph sim --KEY VALUE` applies it"""
        self._check(self.lib.am_api_set(self.work, str(key).encode(), str(value).encode(), self.err, len(self.err)))

    def set_config(self, text, name="config"):
        """replaces the settings with a run folder's config.txt text as `amorph sim DIR` reads it (a key
        it does not name as the run had it; errors "NAME:LINE: problem", the settings unchanged)"""
        self._check(self.lib.am_api_set_config(self.work, text.encode(), str(name).encode(), self.err, len(self.err)))

    @classmethod
    def from_run(cls, path, lib=None):
        """a workspace in the settings of a run folder (or of a config.txt named itself): a genome
        evaluates as that run evaluated it, as `amorph sim DIR --genome FILE` does"""
        name = os.path.join(path, "config.txt") if os.path.isdir(path) else path
        try:
            with open(name) as f:
                text = f.read()
        except OSError as e:
            raise AmorphError("%s: %s" % (name, e.strerror or e))
        except UnicodeDecodeError:
            raise AmorphError("%s: not a text file" % name)
        w = cls(None, lib)
        w.set_config(text, name)
        return w

    def evaluate(self, text):
        """a genome, lattice or VXA text, evaluated as amorph evaluates it (a VXA file in its own
        environment and evaluation, as `amorph sim FILE`): a Result"""
        r = Result()
        head = text.lstrip()
        fn = self.lib.am_api_eval_genome if head.startswith("amorph-genome") else \
            self.lib.am_api_eval_vxa if head.startswith("<") else self.lib.am_api_eval_lattice
        self._check(fn(self.work, text.encode(), ctypes.byref(r), self.err, len(self.err)))
        return r

    # ---- ask/tell ----

    def seed(self, seed):
        """seeds the genome operators' stream: the stream of a run of `seed = SEED`"""
        self._check(self.lib.am_api_seed(self.work, int(seed), self.err, len(self.err)))

    def new_genome(self):
        """a random genome of the settings, as a run's first population draws it (text)"""
        self._check(self.lib.am_api_genome_new(self.work, self._out[0], len(self._out[0]), self.err, len(self.err)))
        return self._out[0].value.decode()

    def pairing(self, n):
        """a generation's pairs: a shuffle of 0..n-1, order[2k] with order[2k + 1]"""
        order = (ctypes.c_int * n)()
        self._check(self.lib.am_api_pairing(self.work, n, order, self.err, len(self.err)))
        return list(order)

    def offspring(self, a, b):
        """two offspring of parents a and b: crossover, then each mutated (texts)"""
        self._check(self.lib.am_api_offspring(self.work, a.encode(), b.encode(), self._out[0], self._out[1], len(self._out[0]),
                                              self.err, len(self.err)))
        return self._out[0].value.decode(), self._out[1].value.decode()

    def mutate(self, genome):
        """the genome mutated once (text)"""
        self._check(self.lib.am_api_mutate(self.work, genome.encode(), self._out[0], len(self._out[0]), self.err, len(self.err)))
        return self._out[0].value.decode()

    def distance(self, a, b):
        """the crowding distance of two genomes' bodies, in [0, 1]"""
        d = ctypes.c_double()
        self._check(self.lib.am_api_distance(self.work, a.encode(), b.encode(), ctypes.byref(d), self.err, len(self.err)))
        return d.value

    def crowd(self, a, fa, b, fb, c1, f1, c2, f2):
        """deterministic crowding's decision: (meets, replaces), meets[k] the parent (0: a, 1: b)
        offspring k + 1 competes with, replaces[k] True when it takes that parent's place. A
        fitness of NaN is a diverged body's (Result.score())"""
        meets, repl = (ctypes.c_int * 2)(), (ctypes.c_int * 2)()
        self._check(self.lib.am_api_crowd(self.work, a.encode(), fa, b.encode(), fb, c1.encode(), f1, c2.encode(), f2, meets, repl,
                                          self.err, len(self.err)))
        return [meets[0], meets[1]], [bool(repl[0]), bool(repl[1])]


def crowding(w, population, generations, seed, evaluate=None):
    """amorph's own run, deterministic crowding, written over the ask/tell calls: a population of
    `population` random genomes from seed, then `generations` generations of pairing, breeding,
    evaluation and crowding. evaluate(text) -> score (default: w.evaluate(text).score()) may be
    any function: the loop is then amorph's variation and replacement around the caller's
    measure. Returns [(genome, score)] of the final population, in member order."""
    if evaluate is None:
        evaluate = lambda text: w.evaluate(text).score()  # noqa: E731
    w.seed(seed)
    pop = [w.new_genome() for _ in range(population)]
    fit = [evaluate(g) for g in pop]
    for _ in range(generations):
        order = w.pairing(population)
        kids = []
        for k in range(0, population, 2):
            kids += w.offspring(pop[order[k]], pop[order[k + 1]])
        kfit = [evaluate(g) for g in kids]
        for k in range(0, population, 2):
            pa, pb = order[k], order[k + 1]
            meets, repl = w.crowd(pop[pa], fit[pa], pop[pb], fit[pb], kids[k], kfit[k], kids[k + 1], kfit[k + 1])
            for c in range(2):
                if repl[c]:
                    p = pb if meets[c] else pa
                    pop[p], fit[p] = kids[k + c], kfit[k + c]
    return list(zip(pop, fit))


try:  # numpy where present: observations as arrays; never required
    import numpy as _np
except ImportError:  # pragma: no cover
    _np = None


class Sim:
    """a robot under control, gym-style (docs/embedding.md, Stepping):

        sim = amorph.Sim({"cycles": 10})
        obs = sim.reset(text)                 # open, settle; actuation starts now
        for t in range(1000):
            obs = sim.step(action, n=10)      # action: each voxel's scale (1 + expansion), None: the sinusoid's

    An action is a sequence of one scale per voxel (NaN: that voxel's sinusoid), or a dict of
    {material index: scale} for whole groups (the others keep their sinusoid); rate (optional, 1/s)
    likewise. An observation is a dict: step, time, com, com_vel, contacts, diverged, hash and, per voxel
    in the order of sim.materials, pos (x, y, z), vel, strain, contact; arrays with numpy, lists
    without. sim.sinusoid() gives each voxel's own scale and rate for the next step: fed back as the
    action every step, the robot moves exactly as Workspace.evaluate moves it."""

    def __init__(self, settings=None, lib=None, workspace=None):
        self.w = workspace or Workspace(settings, lib)
        self.lib, self.nv = self.w.lib, 0

    def _check(self, status):
        self.w._check(status)

    def reset(self, text):
        """opens and settles the robot of a genome, lattice or VXA text; the first observation"""
        w = self.w
        self._check(self.lib.am_api_sim_open(w.work, text.encode(), w.err, len(w.err)))
        self.settled = Result()
        self._check(self.lib.am_api_sim_settle(w.work, ctypes.byref(self.settled), w.err, len(w.err)))
        self.nv = self.lib.am_api_sim_voxels(w.work, None, None)
        mat, cell = (ctypes.c_int * self.nv)(), (ctypes.c_int * self.nv)()
        self.lib.am_api_sim_voxels(w.work, mat, cell)
        self.materials, self.cells = list(mat), list(cell)
        self._scale, self._rate = (ctypes.c_double * self.nv)(), (ctypes.c_double * self.nv)()
        self._pos, self._vel = (ctypes.c_double * (3 * self.nv))(), (ctypes.c_double * (3 * self.nv))()
        self._strain, self._contact = (ctypes.c_double * self.nv)(), (ctypes.c_int * self.nv)()
        return self.observe()

    def _fill(self, buf, values):
        if isinstance(values, dict):
            for i in range(self.nv):
                buf[i] = float(values.get(self.materials[i], math.nan))
        else:
            if len(values) != self.nv:
                raise AmorphError("an action of %d values for %d voxels" % (len(values), self.nv))
            for i in range(self.nv):
                buf[i] = float(values[i])

    def step(self, action=None, n=1, rate=None):
        """n steps with the action held; the observation after them"""
        w = self.w
        if action is None:
            self._check(self.lib.am_api_sim_step(w.work, n, None, None, w.err, len(w.err)))
        else:
            self._fill(self._scale, action)
            if rate is not None:
                self._fill(self._rate, rate)
            self._check(self.lib.am_api_sim_step(w.work, n, self._scale, self._rate if rate is not None else None, w.err, len(w.err)))
        return self.observe()

    def sinusoid(self):
        """each voxel's own scale and rate (1/s) for the next step: (scales, rates)"""
        w = self.w
        self._check(self.lib.am_api_sim_sinusoid(w.work, self._scale, self._rate, w.err, len(w.err)))
        return list(self._scale), list(self._rate)

    def observe(self):
        w, o = self.w, Obs()
        self._check(self.lib.am_api_sim_observe(w.work, ctypes.byref(o), self._pos, self._vel, self._strain, self._contact, w.err,
                                                len(w.err)))
        arr = (lambda b, k: _np.ctypeslib.as_array(b).reshape(-1, k).copy() if k > 1 else _np.ctypeslib.as_array(b).copy()) \
            if _np is not None else (lambda b, k: [tuple(b[i:i + k]) for i in range(0, len(b), k)] if k > 1 else list(b))
        return {"step": o.step, "time": o.time, "com": tuple(o.com), "com_vel": tuple(o.com_vel), "contacts": o.contacts,
                "diverged": bool(o.diverged), "hash": o.hash, "pos": arr(self._pos, 3), "vel": arr(self._vel, 3), "strain": arr(self._strain, 1),
                "contact": arr(self._contact, 1)}
